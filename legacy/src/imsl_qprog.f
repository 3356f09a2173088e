C     [LINKREPRO] STAND-IN FOR THE VANISHED IMSL ROUTINES QPROG AND UMACH
C     (REGISTER D050).  NOT IMSL CODE: WRITTEN FOR THIS PROJECT FROM THE
C     PUBLISHED METHOD (D. GOLDFARB AND A. IDNANI, MATH. PROGRAMMING 27,
C     1983, 1-33), WITH IMSL'S CALLING CONVENTION:
C
C        CALL QPROG (NVAR, NCON, NEQ, A, LDA, B, G, H, LDH, DIAG, SOL,
C                    NACT, IACT, ALAMDA)
C
C     MINIMIZES  G'X + X'HX/2  SUBJECT TO  A(I,.)X = B(I), I=1..NEQ,
C     AND  A(I,.)X >= B(I), I=NEQ+1..NCON.  IF H IS NOT POSITIVE
C     DEFINITE, H + DIAG*I IS USED, DIAG THE SMALLEST MULTIPLE FOUND BY
C     RAISING IT PIVOT BY PIVOT IN THE CHOLESKY FACTORIZATION (D050).
C     OUTPUT: SOL, NACT ACTIVE CONSTRAINTS IACT(1..NACT) WITH LAGRANGE
C     MULTIPLIERS ALAMDA(1..NACT).  A STATUS IS LEFT IN COMMON /QPSTAT/:
C     0 SOLVED, 1 CONSTRAINTS INCONSISTENT, 2 ITERATION LIMIT, 3 BAD
C     ARGUMENTS.  ALL ARITHMETIC IS DOUBLE PRECISION (DQPROG); QPROG
C     IS THE REAL*4 ENTRY, AS IN IMSL.  DQPROG SCALES THE ROWS AND H BY
C     POWERS OF TWO BEFORE SOLVING (QPSOLV), SO THAT THE TOLERANCES ARE
C     RELATIVE TO THE PROBLEM'S OWN SCALE (ISSUE 22).
C
      SUBROUTINE QPROG (NVAR, NCON, NEQ, A, LDA, B, G, H, LDH, DIAG,
     *                  SOL, NACT, IACT, ALAMDA)
      INTEGER NVAR, NCON, NEQ, LDA, LDH, NACT, IACT(*)
      REAL A(LDA,*), B(*), G(*), H(LDH,*), DIAG, SOL(*), ALAMDA(*)
      INTEGER MAXV, MAXC
      PARAMETER (MAXV=60, MAXC=200)
      DOUBLE PRECISION DA(MAXC,MAXV), DB(MAXC), DG(MAXV), DH(MAXV,MAXV),
     *                 DDIAG, DSOL(MAXV), DLAM(MAXC)
      INTEGER I, J, ISTAT
      COMMON /QPSTAT/ ISTAT
      IF (NVAR.LT.1 .OR. NVAR.GT.MAXV .OR. NCON.LT.0 .OR.
     *    NCON.GT.MAXC .OR. NEQ.LT.0 .OR. NEQ.GT.NCON) THEN
         ISTAT = 3
         RETURN
      END IF
      DO 20 J = 1, NVAR
         DG(J) = G(J)
         DO 10 I = 1, NVAR
            DH(I,J) = H(I,J)
   10    CONTINUE
         DO 15 I = 1, NCON
            DA(I,J) = A(I,J)
   15    CONTINUE
   20 CONTINUE
      DO 30 I = 1, NCON
         DB(I) = B(I)
   30 CONTINUE
      CALL DQPROG (NVAR, NCON, NEQ, DA, MAXC, DB, DG, DH, MAXV, DDIAG,
     *             DSOL, NACT, IACT, DLAM)
      DIAG = DDIAG
      DO 40 J = 1, NVAR
         SOL(J) = DSOL(J)
   40 CONTINUE
      DO 50 I = 1, NACT
         ALAMDA(I) = DLAM(I)
   50 CONTINUE
      RETURN
      END
C
      SUBROUTINE DQPROG (NVAR, NCON, NEQ, A, LDA, B, G, H, LDH, DIAG,
     *                   SOL, NACT, IACT, ALAMDA)
C     QPSOLV ON THE PROBLEM IN ITS OWN UNITS (ISSUE 22): ROW I OF A AND
C     B(I) TIMES 2**IRS(I), SO THAT ITS LARGEST |A(I,J)| IS IN [1, 2);
C     H AND G TIMES 4**(-KH), SO THAT THE LARGEST |H(I,J)| OF THE LOWER
C     TRIANGLE (OR OF G WHERE H = 0) IS IN [1, 4).  POWERS OF TWO: THE
C     SCALED NUMBERS HOLD THE SAME DIGITS (L IS SCALED BY 2**(-KH)), A
C     COPY OF THE PROBLEM SCALED BY SUCH POWERS GIVES THE SAME BITS, AND
C     QPSOLV'S TOLERANCES ARE RELATIVE TO THE PROBLEM'S OWN SCALE.  DIAG
C     AND ALAMDA ARE SCALED BACK; SOL IS THE SAME FOR BOTH PROBLEMS.
      INTEGER NVAR, NCON, NEQ, LDA, LDH, NACT, IACT(*)
      DOUBLE PRECISION A(LDA,*), B(*), G(*), H(LDH,*), DIAG, SOL(*),
     *                 ALAMDA(*)
      INTEGER MAXV, MAXC
      PARAMETER (MAXV=60, MAXC=200)
      DOUBLE PRECISION AS(MAXC,MAXV), BS(MAXC), GS(MAXV), HS(MAXV,MAXV),
     *                 BIG, QPHMAX
      INTEGER I, J, K, KH, IRS(MAXC), ISTAT
      COMMON /QPSTAT/ ISTAT
      NACT = 0
      IF (NVAR.LT.1 .OR. NVAR.GT.MAXV .OR. NCON.LT.0 .OR.
     *    NCON.GT.MAXC .OR. NEQ.LT.0 .OR. NEQ.GT.NCON .OR.
     *    NCON.GT.LDA .OR. NVAR.GT.LDH) THEN
         ISTAT = 3
         RETURN
      END IF
      DO 20 I = 1, NCON
         BIG = 0.0D0
         DO 10 J = 1, NVAR
            BIG = MAX(BIG, ABS(A(I,J)))
   10    CONTINUE
         IRS(I) = 0
         IF (BIG.GT.0.0D0) IRS(I) = 1 - EXPONENT(BIG)
         DO 15 J = 1, NVAR
            AS(I,J) = SCALE(A(I,J), IRS(I))
   15    CONTINUE
         BS(I) = SCALE(B(I), IRS(I))
   20 CONTINUE
      BIG = QPHMAX(NVAR, H, LDH)
      IF (BIG.EQ.0.0D0) THEN
         DO 35 J = 1, NVAR
            BIG = MAX(BIG, ABS(G(J)))
   35    CONTINUE
      END IF
      KH = 0
      IF (BIG.GT.0.0D0) KH = FLOOR(0.5D0*DBLE(EXPONENT(BIG) - 1))
      DO 45 J = 1, NVAR
         GS(J) = SCALE(G(J), -2*KH)
         DO 40 I = J, NVAR
            HS(I,J) = SCALE(H(I,J), -2*KH)
   40    CONTINUE
   45 CONTINUE
      CALL QPSOLV (NVAR, NCON, NEQ, AS, MAXC, BS, GS, HS, MAXV, DIAG,
     *             SOL, NACT, IACT, ALAMDA)
      DIAG = SCALE(DIAG, 2*KH)
      DO 50 K = 1, NACT
         ALAMDA(K) = SCALE(ALAMDA(K), 2*KH + IRS(IACT(K)))
   50 CONTINUE
      RETURN
      END
C
      SUBROUTINE QPSOLV (NVAR, NCON, NEQ, A, LDA, B, G, H, LDH, DIAG,
     *                   SOL, NACT, IACT, ALAMDA)
C     THE GOLDFARB-IDNANI METHOD ON THE SCALED PROBLEM (SEE DQPROG).
      INTEGER NVAR, NCON, NEQ, LDA, LDH, NACT, IACT(*)
      DOUBLE PRECISION A(LDA,*), B(*), G(*), H(LDH,*), DIAG, SOL(*),
     *                 ALAMDA(*)
      INTEGER MAXV, MAXC
      PARAMETER (MAXV=60, MAXC=200)
C     L: CHOLESKY FACTOR OF H+DIAG*I.  W: H^-1 TIMES THE NEW NORMAL.
C     GN: H^-1 TIMES THE ACTIVE NORMALS.  M: N'H^-1N.  U: MULTIPLIERS.
C     GN, M AND RHS HOLD AS MANY ACTIVE NORMALS AS THERE ARE CONSTRAINTS:
C     NUMERICALLY DEPENDENT ONES CAN ENTER BEFORE QPGAUS FINDS M SINGULAR.
      DOUBLE PRECISION L(MAXV,MAXV), W(MAXV), Z(MAXV), R(MAXC), U(MAXC),
     *                 GN(MAXV,MAXC), M(MAXC,MAXC), RHS(MAXC),
     *                 SGN(MAXC), ENORM(MAXC)
      DOUBLE PRECISION S, SMIN, T, T1, T2, UPLUS, ZN, PIVOT, SCALE, EPS,
     *                 TOL, TINY, DNEW, QPHMAX
      INTEGER I, J, K, P, KDROP, ITER, MAXIT, ISTAT, JJ
      LOGICAL ACTIVE(MAXC), DONE
      COMMON /QPSTAT/ ISTAT
      EPS = EPSILON(1.0D0)
      ISTAT = 0
      NACT = 0
      IF (NVAR.LT.1 .OR. NVAR.GT.MAXV .OR. NCON.LT.0 .OR.
     *    NCON.GT.MAXC .OR. NEQ.LT.0 .OR. NEQ.GT.NCON .OR.
     *    NCON.GT.LDA .OR. NVAR.GT.LDH) THEN
         ISTAT = 3
         RETURN
      END IF
C     ---- CHOLESKY OF H + DIAG*I, RAISING DIAG WHERE A PIVOT FAILS ----
C     TINY IS RELATIVE TO THE LARGEST |H(I,J)| READ (THE LOWER TRIANGLE;
C     ISSUE 22: MAX |H(I,I)| LEFT A HUGE INDEFINITE H AN INFINITE DIAG)
      SCALE = QPHMAX(NVAR, H, LDH)
      IF (SCALE.EQ.0.0D0) SCALE = 1.0D0
      TINY = SQRT(EPS)*SCALE
      DIAG = 0.0D0
  100 CONTINUE
      DO 130 J = 1, NVAR
         PIVOT = H(J,J) + DIAG
         DO 110 K = 1, J-1
            PIVOT = PIVOT - L(J,K)**2
  110    CONTINUE
         IF (PIVOT.LT.TINY) THEN
C           A SHORTFALL BELOW DIAG'S LAST BIT TAKES THE NEXT NUMBER UP
C           (ELSE STATEMENT 100 WOULD REPEAT THE SAME FACTORIZATION)
            DNEW = DIAG + (TINY - PIVOT)
            IF (DNEW.LE.DIAG) DNEW = NEAREST(DIAG, 1.0D0)
            DIAG = DNEW
            GO TO 100
         END IF
         L(J,J) = SQRT(PIVOT)
         DO 125 I = J+1, NVAR
            S = H(I,J)
            DO 120 K = 1, J-1
               S = S - L(I,K)*L(J,K)
  120       CONTINUE
            L(I,J) = S/L(J,J)
  125    CONTINUE
  130 CONTINUE
C     ---- UNCONSTRAINED MINIMUM: SOL = -(H+DIAG I)^-1 G ----
      DO 140 I = 1, NVAR
         RHS(I) = -G(I)
  140 CONTINUE
      CALL QPCHSL (NVAR, L, MAXV, RHS, SOL)
      DO 150 I = 1, NCON
         ACTIVE(I) = .FALSE.
         SGN(I) = 1.0D0
         ENORM(I) = 0.0D0
         DO 145 J = 1, NVAR
            ENORM(I) = ENORM(I) + A(I,J)**2
  145    CONTINUE
         ENORM(I) = MAX(SQRT(ENORM(I)), 1.0D0)
  150 CONTINUE
      MAXIT = 50*(NCON + NVAR) + 100
      ITER = 0
C     ---- OUTER LOOP: PICK A VIOLATED CONSTRAINT P ----
  200 CONTINUE
      ITER = ITER + 1
      IF (ITER.GT.MAXIT) THEN
         ISTAT = 2
         RETURN
      END IF
      P = 0
      SMIN = 0.0D0
      DO 210 I = 1, NCON
         IF (ACTIVE(I)) GO TO 210
         S = -B(I)
         DO 205 J = 1, NVAR
            S = S + A(I,J)*SOL(J)
  205    CONTINUE
         IF (I.LE.NEQ) THEN
C           AN EQUALITY ENTERS FIRST, TURNED SO THAT IT IS VIOLATED
            SGN(I) = 1.0D0
            IF (S.GT.0.0D0) SGN(I) = -1.0D0
            P = I
            SMIN = SGN(I)*S
            GO TO 220
         END IF
         TOL = 1.0D3*EPS*ENORM(I)*MAX(1.0D0, ABS(B(I)))
         IF (S.LT.-TOL .AND. S/ENORM(I).LT.SMIN) THEN
            P = I
            SMIN = S/ENORM(I)
         END IF
  210 CONTINUE
      IF (P.EQ.0) GO TO 900
  220 CONTINUE
      UPLUS = 0.0D0
C     ---- INNER LOOP: STEP TOWARDS SATISFYING CONSTRAINT P ----
  300 CONTINUE
      ITER = ITER + 1
      IF (ITER.GT.MAXIT) THEN
         ISTAT = 2
         RETURN
      END IF
C     W = H^-1 N+, GN(.,K) = H^-1 N_K FOR THE ACTIVE NORMALS
      DO 305 J = 1, NVAR
         RHS(J) = SGN(P)*A(P,J)
  305 CONTINUE
      CALL QPCHSL (NVAR, L, MAXV, RHS, W)
      DO 320 K = 1, NACT
         JJ = IACT(K)
         DO 310 J = 1, NVAR
            RHS(J) = SGN(JJ)*A(JJ,J)
  310    CONTINUE
         CALL QPCHSL (NVAR, L, MAXV, RHS, GN(1,K))
  320 CONTINUE
C     R = (N'H^-1N)^-1 N'W ; Z = W - GN R
      IF (NACT.GT.0) THEN
         DO 340 I = 1, NACT
            RHS(I) = 0.0D0
            DO 330 J = 1, NVAR
               RHS(I) = RHS(I) + SGN(IACT(I))*A(IACT(I),J)*W(J)
  330       CONTINUE
            DO 336 K = 1, NACT
               M(I,K) = 0.0D0
               DO 335 J = 1, NVAR
                  M(I,K) = M(I,K) + SGN(IACT(I))*A(IACT(I),J)*GN(J,K)
  335          CONTINUE
  336       CONTINUE
  340    CONTINUE
         CALL QPGAUS (NACT, M, MAXC, RHS, R, ISTAT)
         IF (ISTAT.NE.0) THEN
            ISTAT = 1
            RETURN
         END IF
      END IF
      ZN = 0.0D0
      DO 360 J = 1, NVAR
         Z(J) = W(J)
         DO 350 K = 1, NACT
            Z(J) = Z(J) - GN(J,K)*R(K)
  350    CONTINUE
         ZN = ZN + Z(J)*SGN(P)*A(P,J)
  360 CONTINUE
C     PARTIAL STEP T1 (A DUAL VARIABLE REACHES ZERO), FULL STEP T2
      T1 = -1.0D0
      KDROP = 0
      DO 370 K = 1, NACT
         IF (IACT(K).LE.NEQ) GO TO 370
         IF (R(K).GT.EPS*MAX(1.0D0,ABS(U(K)))) THEN
            T = U(K)/R(K)
            IF (KDROP.EQ.0 .OR. T.LT.T1) THEN
               T1 = T
               KDROP = K
            END IF
         END IF
  370 CONTINUE
      S = -B(P)
      DO 375 J = 1, NVAR
         S = S + A(P,J)*SOL(J)
  375 CONTINUE
      S = SGN(P)*S
      T2 = -1.0D0
      IF (ZN.GT.EPS*ENORM(P)**2) T2 = -S/ZN
      IF (T2.LT.0.0D0 .AND. KDROP.EQ.0) THEN
C        NO STEP CAN SATISFY CONSTRAINT P: THE CONSTRAINTS ARE INCONSISTENT
         ISTAT = 1
         RETURN
      END IF
      IF (T2.LT.0.0D0) THEN
C        DUAL STEP ONLY, THEN DROP THE BLOCKING CONSTRAINT
         T = T1
      ELSE IF (KDROP.EQ.0) THEN
         T = T2
      ELSE
         T = MIN(T1, T2)
      END IF
      IF (T2.GE.0.0D0) THEN
         DO 380 J = 1, NVAR
            SOL(J) = SOL(J) + T*Z(J)
  380    CONTINUE
      END IF
      DO 385 K = 1, NACT
         U(K) = U(K) - T*R(K)
  385 CONTINUE
      UPLUS = UPLUS + T
      DONE = T2.GE.0.0D0 .AND. (KDROP.EQ.0 .OR. T2.LE.T1)
      IF (DONE) THEN
C        FULL STEP: P JOINS THE ACTIVE SET
         NACT = NACT + 1
         IACT(NACT) = P
         U(NACT) = UPLUS
         ACTIVE(P) = .TRUE.
         GO TO 200
      END IF
C     PARTIAL STEP: DROP THE ACTIVE CONSTRAINT KDROP, STAY WITH P
      ACTIVE(IACT(KDROP)) = .FALSE.
      DO 390 K = KDROP, NACT-1
         IACT(K) = IACT(K+1)
         U(K) = U(K+1)
  390 CONTINUE
      NACT = NACT - 1
      GO TO 300
C     ---- SOLVED: MULTIPLIERS IN THE ORIGINAL CONSTRAINTS' SENSE ----
  900 CONTINUE
      DO 910 K = 1, NACT
         ALAMDA(K) = SGN(IACT(K))*U(K)
  910 CONTINUE
      RETURN
      END
C
      DOUBLE PRECISION FUNCTION QPHMAX (N, H, LDH)
C     THE LARGEST |H(I,J)| OF THE LOWER TRIANGLE (THE PART QPROG READS).
      INTEGER N, LDH, I, J
      DOUBLE PRECISION H(LDH,*)
      QPHMAX = 0.0D0
      DO 20 J = 1, N
         DO 10 I = J, N
            QPHMAX = MAX(QPHMAX, ABS(H(I,J)))
   10    CONTINUE
   20 CONTINUE
      RETURN
      END
C
      SUBROUTINE QPCHSL (N, L, LDL, RHS, X)
C     SOLVE (L L') X = RHS WITH THE CHOLESKY FACTOR L (LOWER TRIANGLE).
      INTEGER N, LDL, I, K
      DOUBLE PRECISION L(LDL,*), RHS(*), X(*), S
      DO 20 I = 1, N
         S = RHS(I)
         DO 10 K = 1, I-1
            S = S - L(I,K)*X(K)
   10    CONTINUE
         X(I) = S/L(I,I)
   20 CONTINUE
      DO 40 I = N, 1, -1
         S = X(I)
         DO 30 K = I+1, N
            S = S - L(K,I)*X(K)
   30    CONTINUE
         X(I) = S/L(I,I)
   40 CONTINUE
      RETURN
      END
C
      SUBROUTINE QPGAUS (N, M, LDM, RHS, X, INFO)
C     SOLVE M X = RHS BY GAUSSIAN ELIMINATION WITH PARTIAL PIVOTING
C     (M AND RHS ARE OVERWRITTEN).  INFO = 1 IF M IS SINGULAR.
      INTEGER N, LDM, INFO, I, J, K, IP
      DOUBLE PRECISION M(LDM,*), RHS(*), X(*), T, BIG
      INFO = 0
      BIG = 0.0D0
      DO 5 I = 1, N
         DO 4 J = 1, N
            BIG = MAX(BIG, ABS(M(I,J)))
    4    CONTINUE
    5 CONTINUE
      DO 40 K = 1, N
         IP = K
         DO 10 I = K+1, N
            IF (ABS(M(I,K)).GT.ABS(M(IP,K))) IP = I
   10    CONTINUE
         IF (ABS(M(IP,K)).LE.1.0D-14*BIG) THEN
            INFO = 1
            RETURN
         END IF
         IF (IP.NE.K) THEN
            DO 15 J = 1, N
               T = M(K,J)
               M(K,J) = M(IP,J)
               M(IP,J) = T
   15       CONTINUE
            T = RHS(K)
            RHS(K) = RHS(IP)
            RHS(IP) = T
         END IF
         DO 30 I = K+1, N
            T = M(I,K)/M(K,K)
            DO 20 J = K, N
               M(I,J) = M(I,J) - T*M(K,J)
   20       CONTINUE
            RHS(I) = RHS(I) - T*RHS(K)
   30    CONTINUE
   40 CONTINUE
      DO 60 I = N, 1, -1
         T = RHS(I)
         DO 50 J = I+1, N
            T = T - M(I,J)*X(J)
   50    CONTINUE
         X(I) = T/M(I,I)
   60 CONTINUE
      RETURN
      END
C
      SUBROUTINE QPSTAT_GET (ISTAT_OUT)
C     THE STATUS OF THE LAST QPROG CALL (FOR THE PYTHON FACE).
      INTEGER ISTAT_OUT, ISTAT
      COMMON /QPSTAT/ ISTAT
      ISTAT_OUT = ISTAT
      RETURN
      END
C
      SUBROUTINE UMACH (N, NUNIT)
C     IMSL UMACH: N=1 STANDARD INPUT UNIT, N=2 STANDARD OUTPUT UNIT.
      INTEGER N, NUNIT
      NUNIT = 6
      IF (N.EQ.1 .OR. N.EQ.-1) NUNIT = 5
      RETURN
      END
