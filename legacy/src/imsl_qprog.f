C     [LINKREPRO] STAND-IN FOR THE VANISHED IMSL ROUTINES QPROG AND UMACH
C     (REGISTER D050).  NOT IMSL CODE: WRITTEN FOR THIS PROJECT FROM THE
C     PUBLISHED METHOD (D. GOLDFARB AND A. IDNANI, MATH. PROGRAMMING 27,
C     1983, 1-33), WITH IMSL'S CALLING CONVENTION:
C
C        CALL QPROG (NVAR, NCON, NEQ, A, LDA, B, G, H, LDH, DIAG, SOL,
C                    NACT, IACT, ALAMDA)
C
C     MINIMIZES  G'X + X'HX/2  SUBJECT TO  A(I,.)X = B(I), I=1..NEQ,
C     AND  A(I,.)X >= B(I), I=NEQ+1..NCON.  H IS SOLVED AS GIVEN WHERE
C     ITS CHOLESKY FACTORIZATION HAS EVERY PIVOT AT LEAST NVAR*EPS*
C     MAX|H(I,J)| (POSITIVE DEFINITE TO ITS ROUNDING, DIAG = 0; D160).
C     ELSE H + DIAG*I IS USED, DIAG FOUND BY RAISING IT PIVOT BY PIVOT IN
C     THE CHOLESKY FACTORIZATION (D050): THE ANSWER IS THEN THE
C     REGULARIZED PROBLEM'S.  OUTPUT: SOL, NACT ACTIVE CONSTRAINTS
C     IACT(1..NACT) WITH LAGRANGE MULTIPLIERS ALAMDA(1..NACT).  A STATUS
C     IS LEFT IN COMMON /QPSTAT/: 0 SOLVED, 1 CONSTRAINTS INCONSISTENT,
C     2 ITERATION LIMIT, 3 BAD ARGUMENTS, 4 THE SOLUTION FOUND MISSES A
C     CONSTRAINT BY MORE THAN THE METHOD'S ROUNDING (QPSOLV'S LAST GUARD,
C     ISSUE 22), 5 UNBOUNDED BELOW (D163); AND IN COMMON /QPCND/ QCOND,
C     THE CONDITION OF THE ANSWER ON THE DIRECTIONS H DETERMINES (D160,
C     QPCOND).  THE REAL*4 ENTRY QPROG COUNTS IN COMMON /QPWARN/ THE
C     CALLS WHOSE ANSWER SINGLE PRECISION CANNOT CARRY (D161).  A SOLVED
C     SOL MEETS EVERY ROW TO EPS*(1E3 + 8 KAPPA) OF |A(I,.)||SOL|+|B(I)|,
C     KAPPA = TRACE(H+DIAG*I)*TRACE((H+DIAG*I)^-1) >= ITS CONDITION
C     NUMBER.  ALL ARITHMETIC IS DOUBLE PRECISION (DQPROG); QPROG
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
      DOUBLE PRECISION QCOND, WERR, TRH, ERR, US                        ! D161
      INTEGER I, J, ISTAT, NWARN                                        ! D161
      COMMON /QPSTAT/ ISTAT
      COMMON /QPCND/ QCOND                                              ! D161
      COMMON /QPWARN/ WERR, NWARN                                       ! D161
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
C     D161: THE ANSWER'S RELATIVE ERROR ON THE DIRECTIONS H DETERMINES,
C     QCOND*(US + DIAG/TRACE(H)): H'S OWN REAL*4 ROUNDING (US = 2**-24)
C     AND THE REGULARIZATION.  AT 1 OR MORE SINGLE PRECISION CARRIES NO
C     DIGIT OF IT: THE CALL IS COUNTED, THE WORST ERROR KEPT (QPWARN_GET)
      IF (ISTAT.EQ.0) THEN                                              ! D161
         US = 0.5D0*EPSILON(1.0E0)                                      ! D161
         TRH = 0.0D0                                                    ! D161
         DO 35 J = 1, NVAR                                              ! D161
            TRH = TRH + DH(J,J)                                         ! D161
   35    CONTINUE                                                       ! D161
         ERR = QCOND*US                                                 ! D161
         IF (TRH.GT.0.0D0) ERR = QCOND*(US + DDIAG/TRH)                 ! D161
         IF (ERR.GE.1.0D0) THEN                                         ! D161
            NWARN = NWARN + 1                                           ! D161
            WERR = MAX(WERR, ERR)                                       ! D161
         END IF                                                         ! D161
      END IF                                                            ! D161
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
      DOUBLE PRECISION QCOND, QC, DZ, SOLZ(MAXV), ALAMZ(MAXC)           ! D163
      INTEGER NACTZ, IACTZ(MAXC)                                        ! D163
      COMMON /QPSTAT/ ISTAT
      COMMON /QPCND/ QCOND                                              ! D163
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
     *             SOL, NACT, IACT, ALAMDA, .FALSE.)                    ! D163
C     D163: WHERE H WAS SHIFTED, THE RECESSION PROBLEM (B = 0: ITS ROWS
C     ARE THE DIRECTIONS ALONG WHICH EVERY ROW STAYS FEASIBLE) DECIDES
C     WHETHER THE PROBLEM IS UNBOUNDED BELOW (QPSOLV, QPUNBD): STATUS 5
      IF (ISTAT.EQ.0 .AND. DIAG.GT.0.0D0) THEN                          ! D163
         QC = QCOND                                                     ! D163
         DO 47 I = 1, NCON                                              ! D163
            BS(I) = 0.0D0                                               ! D163
   47    CONTINUE                                                       ! D163
         CALL QPSOLV (NVAR, NCON, NEQ, AS, MAXC, BS, GS, HS, MAXV, DZ,  ! D163
     *                SOLZ, NACTZ, IACTZ, ALAMZ, .TRUE.)                ! D163
         IF (ISTAT.NE.5) ISTAT = 0                                      ! D163
         QCOND = QC                                                     ! D163
      END IF                                                            ! D163
      DIAG = SCALE(DIAG, 2*KH)
      DO 50 K = 1, NACT
         ALAMDA(K) = SCALE(ALAMDA(K), 2*KH + IRS(IACT(K)))
   50 CONTINUE
      RETURN
      END
C
      SUBROUTINE QPSOLV (NVAR, NCON, NEQ, A, LDA, B, G, H, LDH, DIAG,
     *                   SOL, NACT, IACT, ALAMDA, RECESS)               ! D163
C     THE GOLDFARB-IDNANI METHOD ON THE SCALED PROBLEM (SEE DQPROG).
C     ISSUE 22 (A VIOLATED ROW DEPENDENT ON THE ACTIVE ONES WAS ADDED AS
C     IF INDEPENDENT, AND INFEASIBLE PROBLEMS RETURNED AS SOLVED): Z = 0
C     IS DECIDED AGAINST THE ROUNDING OF ZN (ZR), THE ROW TESTS ARE
C     RELATIVE TO |A(I,.)||SOL| + |B(I)| (QPROW), A DEPENDENT EQUALITY
C     THAT HOLDS IS HELD INSTEAD OF REFUSED, A FULL STEP PROJECTS SOL
C     BACK ONTO THE ACTIVE ROWS WHERE ROUNDING LEFT THEM OFF (QPRFN),
C     AND NO SOL IS RETURNED THAT MISSES A ROW BY MORE THAN GTOL.
C     A DEFINITE H IS SOLVED AS GIVEN (D160), A ROW THAT
C     DEPENDS ON THE ACTIVE ONES AND HOLDS TO GTOL IS HELD (D162), AND
C     QCOND IS LEFT (D160).  WHERE DIAG > 0, STATUS 5 WHERE QPUNBD
C     CERTIFIES FROM SOL THAT THE PROBLEM IS UNBOUNDED (D163); RECESS:
C     THIS IS THE RECESSION PROBLEM (B = 0), SOLVED FOR THAT ALONE.
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
      DOUBLE PRECISION MC(MAXC,MAXC), CG(MAXC), STOL                    ! D160
      DOUBLE PRECISION S, SMIN, T, T1, T2, UPLUS, ZN, PIVOT, SCALE, EPS,
     *                 TOL, TINY, DNEW, QPHMAX, ZR, SIZE, GTOL, QPKAPP
      DOUBLE PRECISION QCOND, QPCOND                                    ! D160
      INTEGER I, J, K, P, KDROP, ITER, MAXIT, ISTAT
C     HELD(I): ROW I HOLDS AND DEPENDS ON THE ACTIVE ROWS; NOT ADDED,
C     AND NOT PICKED AGAIN UNTIL SOL MOVES
      LOGICAL ACTIVE(MAXC), HELD(MAXC), DONE
      LOGICAL DEFNT, QPUNBD, QPINDP                                     ! D160
      LOGICAL RECESS                                                    ! D163
      COMMON /QPSTAT/ ISTAT
      COMMON /QPCND/ QCOND                                              ! D160
      EPS = EPSILON(1.0D0)
      ISTAT = 0
      NACT = 0
      QCOND = 0.0D0                                                     ! D160
      IF (NVAR.LT.1 .OR. NVAR.GT.MAXV .OR. NCON.LT.0 .OR.
     *    NCON.GT.MAXC .OR. NEQ.LT.0 .OR. NEQ.GT.NCON .OR.
     *    NCON.GT.LDA .OR. NVAR.GT.LDH) THEN
         ISTAT = 3
         RETURN
      END IF
C     ---- CHOLESKY OF H + DIAG*I, RAISING DIAG WHERE A PIVOT FAILS ----
C     TINY IS RELATIVE TO THE LARGEST |H(I,J)| READ (THE LOWER TRIANGLE;
C     ISSUE 22: MAX |H(I,I)| LEFT A HUGE INDEFINITE H AN INFINITE DIAG)
C     D160: FIRST WITH DIAG = 0 AND TINY = NVAR*EPS*SCALE, THE ROUNDING
C     OF A PIVOT: WHERE EVERY PIVOT PASSES (AND KAPPA, AFTER 130, STAYS
C     WITHIN 1/(NVAR EPS)), H IS POSITIVE DEFINITE TO ITS ROUNDING AND
C     SOLVED AS GIVEN (A CONDITION OF 1E14 INCLUDED); ELSE THE DIAG RULE
C     RUNS AS BEFORE, FROM DIAG = 0 WITH SQRT(EPS)*SCALE
      SCALE = QPHMAX(NVAR, H, LDH)
      IF (SCALE.EQ.0.0D0) SCALE = 1.0D0
      DEFNT = .TRUE.                                                    ! D160
      TINY = DBLE(NVAR)*EPS*SCALE                                       ! D160
      DIAG = 0.0D0
  100 CONTINUE
      DO 130 J = 1, NVAR
         PIVOT = H(J,J) + DIAG
         DO 110 K = 1, J-1
            PIVOT = PIVOT - L(J,K)**2
  110    CONTINUE
         IF (PIVOT.LT.TINY .AND. DEFNT) THEN                            ! D160
            DEFNT = .FALSE.                                             ! D160
            TINY = SQRT(EPS)*SCALE                                      ! D160
            GO TO 100                                                   ! D160
         END IF                                                         ! D160
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
C     D160: AND KAPPA = TR(H) TR(H^-1) >= COND(H) WITHIN 1/(NVAR EPS): NO
C     PERTURBATION OF H OF THE SIZE OF ITS ROUNDING MAKES IT SINGULAR
      IF (DEFNT) THEN                                                   ! D160
         IF (DBLE(NVAR)*EPS*QPKAPP(NVAR, H, LDH, DIAG, L, MAXV, W, Z)   ! D160
     *       .GT.1.0D0) THEN                                            ! D160
            DEFNT = .FALSE.                                             ! D160
            TINY = SQRT(EPS)*SCALE                                      ! D160
            GO TO 100                                                   ! D160
         END IF                                                         ! D160
      END IF                                                            ! D160
C     GTOL: HOW FAR A SOLVED SOL MAY MISS A ROW, RELATIVE TO ITS SIZE:
C     1E3 EPS, AND 8 EPS KAPPA FOR THE ROUNDING OF THE METHOD WHERE
C     H + DIAG*I IS ILL-CONDITIONED (ISSUE 22)
      GTOL = EPS*(1.0D3 + 8.0D0*QPKAPP(NVAR, H, LDH, DIAG, L, MAXV, W,
     *                                 Z))
C     STOL: HOW FAR THE STATIONARITY MAY MISS BEFORE QPRFN REFINES IT:
C     1E3 EPS WHERE H IS SOLVED AS GIVEN, GTOL WHERE DIAG > 0 (D160)
      STOL = GTOL                                                       ! D160
      IF (DIAG.EQ.0.0D0) STOL = 1.0D3*EPS                               ! D160
C     ---- UNCONSTRAINED MINIMUM: SOL = -(H+DIAG I)^-1 G ----
      DO 140 I = 1, NVAR
         RHS(I) = -G(I)
  140 CONTINUE
      CALL QPCHSL (NVAR, L, MAXV, RHS, SOL)
      DO 150 I = 1, NCON
         ACTIVE(I) = .FALSE.
         HELD(I) = .FALSE.
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
         IF (ACTIVE(I) .OR. HELD(I)) GO TO 210
         CALL QPROW (NVAR, A, LDA, B, I, SOL, S, SIZE)
         IF (I.LE.NEQ) THEN
C           AN EQUALITY ENTERS FIRST, TURNED SO THAT IT IS VIOLATED
            SGN(I) = 1.0D0
            IF (S.GT.0.0D0) SGN(I) = -1.0D0
            P = I
            SMIN = SGN(I)*S
            GO TO 220
         END IF
C        VIOLATED BEYOND ITS ROUNDING (ISSUE 22: WAS 1E3 EPS |A(I,.)|
C        MAX(1, |B(I)|), ABSOLUTE IN SOL'S SCALE)
         TOL = 1.0D3*EPS*SIZE
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
      CALL QPNMAT (NVAR, NACT, IACT, SGN, A, LDA, L, MAXV, GN, M, MAXC,
     *             RHS)
C     R = (N'H^-1N)^-1 N'W ; Z = W - GN R
      IF (NACT.GT.0) THEN
         DO 340 I = 1, NACT
            RHS(I) = 0.0D0
            DO 330 J = 1, NVAR
               RHS(I) = RHS(I) + SGN(IACT(I))*A(IACT(I),J)*W(J)
  330       CONTINUE
  340    CONTINUE
         CALL QPGAUS (NACT, M, MAXC, RHS, R, ISTAT)
         IF (ISTAT.NE.0) THEN
            ISTAT = 1
            RETURN
         END IF
      END IF
C     ZR: THE SIZE OF THE TERMS OF ZN, THE SCALE OF ITS ROUNDING
      ZN = 0.0D0
      ZR = 0.0D0
      DO 360 J = 1, NVAR
         Z(J) = W(J)
         SIZE = ABS(W(J))
         DO 350 K = 1, NACT
            Z(J) = Z(J) - GN(J,K)*R(K)
            SIZE = SIZE + ABS(GN(J,K)*R(K))
  350    CONTINUE
         ZN = ZN + Z(J)*SGN(P)*A(P,J)
         ZR = ZR + SIZE*ABS(A(P,J))
  360 CONTINUE
C     PARTIAL STEP T1 (A DUAL VARIABLE REACHES ZERO), FULL STEP T2
      T1 = -1.0D0
      KDROP = 0
      DO 370 K = 1, NACT
         IF (IACT(K).LE.NEQ) GO TO 370
C        R IS FREE OF UNITS (ISSUE 22: WAS EPS*MAX(1,|U(K)|), U IN G'S)
         IF (R(K).GT.EPS) THEN
            T = U(K)/R(K)
            IF (KDROP.EQ.0 .OR. T.LT.T1) THEN
               T1 = T
               KDROP = K
            END IF
         END IF
  370 CONTINUE
      CALL QPROW (NVAR, A, LDA, B, P, SOL, S, SIZE)
      S = SGN(P)*S
C     Z = 0 (N+ DEPENDS ON THE ACTIVE NORMALS) UNLESS ZN STANDS ABOVE ITS
C     ROUNDING (ISSUE 22: THE TEST WAS ZN > EPS |N+|**2, WHICH ROUNDING
C     PASSED, AND A FULL STEP OF S/ZN ~ 1E14 ALONG NOISE ADDED P)
C     D160: WHERE H IS ILL-CONDITIONED ZN FALLS BELOW 1E3 EPS ZR FOR AN
C     INDEPENDENT ROW TOO: THEN A POSITIVE ZN IS TAKEN IF N+ IS
C     INDEPENDENT OF THE ACTIVE NORMALS (QPINDP)
      T2 = -1.0D0
      IF (ZN.GT.1.0D3*EPS*ZR) THEN                                      ! D160
         T2 = -S/ZN                                                     ! D160
      ELSE IF (ZN.GT.0.0D0 .AND. NACT.GT.0) THEN                        ! D160
         IF (QPINDP(NVAR, A, LDA, IACT, NACT, P, M, MAXC, RHS, CG))     ! D160
     *      T2 = -S/ZN                                                  ! D160
      END IF                                                            ! D160
C     A DEPENDENT ROW THAT HOLDS (A REPEATED ROW, 0 X = 0, AN INEQUALITY
C     REPEATING AN ACTIVE EQUALITY) TO THE METHOD'S OWN ROUNDING GTOL
C     (D162: WAS 1E3 EPS |ROW|, EQUALITIES ONLY: 'INCONSISTENT')
      IF (T2.LT.0.0D0 .AND. UPLUS.EQ.0.0D0 .AND.                        ! D162
     *    -S.LE.GTOL*SIZE) THEN                                         ! D162
         HELD(P) = .TRUE.
         GO TO 200
      END IF
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
         DO 382 I = 1, NCON
            HELD(I) = .FALSE.
  382    CONTINUE
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
         CALL QPRFN (NVAR, NACT, IACT, SGN, A, LDA, B, L, MAXV, GTOL,
     *               SOL, U, GN, M, MAXC, RHS, R, W, H, LDH, G, DIAG,   ! D160
     *               STOL, Z)                                           ! D160
C        D160: AN INEQUALITY'S MULTIPLIER THE REFINEMENT LEFT NEGATIVE:
C        DROP THAT ROW (THE METHOD KEEPS U >= 0), REFINE ON THE REST
  386    IF (DIAG.EQ.0.0D0) THEN                                        ! D160
            KDROP = 0                                                   ! D160
            T = 0.0D0                                                   ! D160
            DO 387 K = 1, NACT                                          ! D160
               IF (IACT(K).GT.NEQ .AND. U(K).LT.T) THEN                 ! D160
                  T = U(K)                                              ! D160
                  KDROP = K                                             ! D160
               END IF                                                   ! D160
  387       CONTINUE                                                    ! D160
            IF (KDROP.GT.0) THEN                                        ! D160
               ACTIVE(IACT(KDROP)) = .FALSE.                            ! D160
               DO 388 K = KDROP, NACT-1                                 ! D160
                  IACT(K) = IACT(K+1)                                   ! D160
                  U(K) = U(K+1)                                         ! D160
  388          CONTINUE                                                 ! D160
               NACT = NACT - 1                                          ! D160
               CALL QPRFN (NVAR, NACT, IACT, SGN, A, LDA, B, L, MAXV,   ! D160
     *                     GTOL, SOL, U, GN, M, MAXC, RHS, R, W, H, LDH,! D160
     *                     G, DIAG, STOL, Z)                            ! D160
               GO TO 386                                                ! D160
            END IF                                                      ! D160
         END IF                                                         ! D160
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
C     ---- SOLVED: THE LAST GUARD (ISSUE 22), THEN THE MULTIPLIERS IN
C     THE ORIGINAL CONSTRAINTS' SENSE ----
  900 CONTINUE
      DO 905 I = 1, NCON
         CALL QPROW (NVAR, A, LDA, B, I, SOL, S, SIZE)
         IF (I.LE.NEQ) S = -ABS(S)
         IF (S.LT.-GTOL*SIZE) THEN
            ISTAT = 4
            RETURN
         END IF
  905 CONTINUE
      IF (DIAG.GT.0.0D0) THEN                                           ! D163
         IF (QPUNBD(NVAR, NCON, NEQ, A, LDA, G, H, LDH, L, MAXV, SGN,   ! D163
     *              IACT, NACT, SOL, GN, M, MAXC, RHS, R, W, Z)) THEN   ! D163
            ISTAT = 5                                                   ! D163
            RETURN                                                      ! D163
         END IF                                                         ! D163
      END IF                                                            ! D163
      IF (RECESS) RETURN                                                ! D163
      QCOND = QPCOND(NVAR, NACT, IACT, SGN, A, LDA, H, LDH, L, MAXV,    ! D160
     *               GN, M, MC, MAXC, RHS, R, W, Z)                     ! D160
      DO 910 K = 1, NACT
         ALAMDA(K) = SGN(IACT(K))*U(K)
  910 CONTINUE
      RETURN
      END
C
      SUBROUTINE QPROW (NVAR, A, LDA, B, I, SOL, S, SIZE)
C     S = A(I,.)SOL - B(I), SUMMED FROM -B(I) IN THE ORDER OF THE
C     VARIABLES, AND SIZE = |B(I)| + SUM |A(I,J)SOL(J)|, THE SCALE OF ITS
C     ROUNDING (ISSUE 22).
      INTEGER NVAR, LDA, I, J
      DOUBLE PRECISION A(LDA,*), B(*), SOL(*), S, SIZE
      S = -B(I)
      SIZE = ABS(B(I))
      DO 10 J = 1, NVAR
         S = S + A(I,J)*SOL(J)
         SIZE = SIZE + ABS(A(I,J)*SOL(J))
   10 CONTINUE
      RETURN
      END
C
      SUBROUTINE QPNMAT (NVAR, NACT, IACT, SGN, A, LDA, L, LDL, GN, M,
     *                   LDM, E)
C     FOR THE ACTIVE NORMALS N_K = SGN*A(IACT(K),.): GN(.,K) = H^-1 N_K
C     (H = L L') AND M = N'H^-1N.  E IS A WORK ARRAY OF LENGTH NVAR.
      INTEGER NVAR, NACT, IACT(*), LDA, LDL, LDM, I, J, K, JJ
      DOUBLE PRECISION SGN(*), A(LDA,*), L(LDL,*), GN(LDL,*), M(LDM,*),
     *                 E(*)
      DO 20 K = 1, NACT
         JJ = IACT(K)
         DO 10 J = 1, NVAR
            E(J) = SGN(JJ)*A(JJ,J)
   10    CONTINUE
         CALL QPCHSL (NVAR, L, LDL, E, GN(1,K))
   20 CONTINUE
      DO 50 I = 1, NACT
         DO 40 K = 1, NACT
            M(I,K) = 0.0D0
            DO 30 J = 1, NVAR
               M(I,K) = M(I,K) + SGN(IACT(I))*A(IACT(I),J)*GN(J,K)
   30       CONTINUE
   40    CONTINUE
   50 CONTINUE
      RETURN
      END
C
      SUBROUTINE QPRFN (NVAR, NACT, IACT, SGN, A, LDA, B, L, LDL, GTOL,
     *                  SOL, U, GN, M, LDM, RHS, R, W, H, LDH, G, DIAG, ! D160
     *                  STOL, E)                                        ! D160
C     WHERE AN ACTIVE ROW MISSES ITS BOUND BY MORE THAN GTOL OF ITS SIZE
C     (ROUNDING IN THE STEPS, E.G. FROM AN UNCONSTRAINED MINIMUM FAR OUT),
C     OR (D160) A COMPONENT OF THE STATIONARITY RESIDUAL E = (H+DIAG I)
C     SOL + G - N U BY MORE THAN STOL OF THE SIZE OF ITS TERMS, AT MOST
C     TWO SWEEPS OF REFINEMENT OF THE KKT SYSTEM ON THE ACTIVE SET:
C     SOL = SOL + GN Y - (H+DIAG I)^-1 E,  U = U + Y,  (N'H^-1N) Y =
C     N'(H+DIAG I)^-1 E - (N'SOL - B).  WITHOUT A STATIONARITY MISS E IS
C     NOT USED (SOL = SOL + GN Y, AS ISSUE 22 HAD IT).  GN, M, RHS, R, W
C     AND E: QPSOLV'S WORK.
      INTEGER NVAR, NACT, IACT(*), LDA, LDL, LDM, J, K, SWEEP, INFO
      INTEGER LDH, I                                                    ! D160
      DOUBLE PRECISION SGN(*), A(LDA,*), B(*), L(LDL,*), GTOL, SOL(*),
     *                 U(*), GN(LDL,*), M(LDM,*), RHS(*), R(*), W(*),
     *                 S, SIZE
      DOUBLE PRECISION H(LDH,*), G(*), DIAG, STOL, E(*), T, HJI         ! D160
      LOGICAL OFF, STAT                                                 ! D160
      DO 40 SWEEP = 1, 2
         OFF = .FALSE.
         DO 10 K = 1, NACT
            CALL QPROW (NVAR, A, LDA, B, IACT(K), SOL, S, SIZE)
            RHS(K) = -(SGN(IACT(K))*S)
            IF (ABS(S).GT.GTOL*SIZE) OFF = .TRUE.
   10    CONTINUE
         STAT = .TRUE.                                                  ! D160
         DO 14 J = 1, NVAR                                              ! D160
            S = G(J) + DIAG*SOL(J)                                      ! D160
            SIZE = ABS(G(J)) + ABS(DIAG*SOL(J))                         ! D160
            DO 12 I = 1, NVAR                                           ! D160
               IF (J.GE.I) HJI = H(J,I)                                 ! D160
               IF (J.LT.I) HJI = H(I,J)                                 ! D160
               S = S + HJI*SOL(I)                                       ! D160
               SIZE = SIZE + ABS(HJI*SOL(I))                            ! D160
   12       CONTINUE                                                    ! D160
            DO 13 K = 1, NACT                                           ! D160
               T = SGN(IACT(K))*A(IACT(K),J)*U(K)                       ! D160
               S = S - T                                                ! D160
               SIZE = SIZE + ABS(T)                                     ! D160
   13       CONTINUE                                                    ! D160
            E(J) = S                                                    ! D160
            IF (ABS(S).GT.STOL*SIZE) STAT = .FALSE.                     ! D160
   14    CONTINUE                                                       ! D160
         IF (.NOT.OFF .AND. STAT) RETURN                                ! D160
         CALL QPNMAT (NVAR, NACT, IACT, SGN, A, LDA, L, LDL, GN, M, LDM,
     *                W)
         IF (.NOT.STAT) THEN                                            ! D160
            CALL QPCHSL (NVAR, L, LDL, E, W)                            ! D160
            DO 18 K = 1, NACT                                           ! D160
               S = RHS(K)                                               ! D160
               DO 17 J = 1, NVAR                                        ! D160
                  S = S + SGN(IACT(K))*A(IACT(K),J)*W(J)                ! D160
   17          CONTINUE                                                 ! D160
               RHS(K) = S                                               ! D160
   18       CONTINUE                                                    ! D160
         END IF                                                         ! D160
         CALL QPGAUS (NACT, M, LDM, RHS, R, INFO)
         IF (INFO.NE.0) RETURN
         DO 30 J = 1, NVAR
            S = SOL(J)
            IF (.NOT.STAT) S = S - W(J)                                 ! D160
            DO 20 K = 1, NACT
               S = S + GN(J,K)*R(K)
   20       CONTINUE
            SOL(J) = S
   30    CONTINUE
         DO 35 K = 1, NACT
            U(K) = U(K) + R(K)
   35    CONTINUE
   40 CONTINUE
      RETURN
      END
C
      LOGICAL FUNCTION QPINDP (NVAR, A, LDA, IACT, NACT, P, GRAM, LDG,  ! D160
     *                         RHS, C)                                  ! D160
C     D160: IS ROW P'S NORMAL INDEPENDENT OF THE ACTIVE NORMALS, IN THE
C     PLAIN (EUCLIDEAN) SENSE?  THE LEAST-SQUARES RESIDUAL RHO = N+ - N C,
C     (N'N) C = N'N+, STANDS IN SOME COMPONENT ABOVE 1E3 EPS OF THE
C     LARGEST SIZE OF ITS TERMS; NOT WHERE N'N IS SINGULAR.  WHERE H IS
C     ILL-CONDITIONED ZN FALLS BELOW 1E3 EPS ZR FOR INDEPENDENT ROWS TOO
C     (ZR GROWS WITH COND(H)), WHILE A DEPENDENT NORMAL (A REPEATED OR
C     SUMMED ROW, MORE ROWS THAN VARIABLES) LEAVES RHO AT ITS ROUNDING.
      INTEGER NVAR, LDA, IACT(*), NACT, P, LDG, I, J, K, INFO           ! D160
      DOUBLE PRECISION A(LDA,*), GRAM(LDG,*), RHS(*), C(*), S, T, SIZE, ! D160
     *                 BIG, SCL                                         ! D160
      DO 20 I = 1, NACT                                                 ! D160
         DO 10 K = 1, NACT                                              ! D160
            S = 0.0D0                                                   ! D160
            DO 5 J = 1, NVAR                                            ! D160
               S = S + A(IACT(I),J)*A(IACT(K),J)                        ! D160
    5       CONTINUE                                                    ! D160
            GRAM(I,K) = S                                               ! D160
   10    CONTINUE                                                       ! D160
         S = 0.0D0                                                      ! D160
         DO 15 J = 1, NVAR                                              ! D160
            S = S + A(IACT(I),J)*A(P,J)                                 ! D160
   15    CONTINUE                                                       ! D160
         RHS(I) = S                                                     ! D160
   20 CONTINUE                                                          ! D160
      QPINDP = .FALSE.                                                  ! D160
      CALL QPGAUS (NACT, GRAM, LDG, RHS, C, INFO)                       ! D160
      IF (INFO.NE.0) RETURN                                             ! D160
      BIG = 0.0D0                                                       ! D160
      SCL = 0.0D0                                                       ! D160
      DO 40 J = 1, NVAR                                                 ! D160
         S = A(P,J)                                                     ! D160
         SIZE = ABS(A(P,J))                                             ! D160
         DO 30 K = 1, NACT                                              ! D160
            T = A(IACT(K),J)*C(K)                                       ! D160
            S = S - T                                                   ! D160
            SIZE = SIZE + ABS(T)                                        ! D160
   30    CONTINUE                                                       ! D160
         BIG = MAX(BIG, ABS(S))                                         ! D160
         SCL = MAX(SCL, SIZE)                                           ! D160
   40 CONTINUE                                                          ! D160
      QPINDP = BIG.GT.1.0D3*EPSILON(1.0D0)*SCL                          ! D160
      RETURN                                                            ! D160
      END                                                               ! D160
C
      DOUBLE PRECISION FUNCTION QPKAPP (N, H, LDH, DIAG, L, LDL, E, Y)
C     TRACE(H + DIAG*I) * TRACE((H + DIAG*I)^-1) FROM THE CHOLESKY
C     FACTOR L: AT LEAST THE CONDITION NUMBER OF H + DIAG*I, AT MOST N**2
C     TIMES IT (ISSUE 22).  E AND Y ARE WORK ARRAYS OF LENGTH N.
      INTEGER N, LDH, LDL, I, J
      DOUBLE PRECISION H(LDH,*), DIAG, L(LDL,*), E(*), Y(*), TH, TI
      TH = 0.0D0
      TI = 0.0D0
      DO 20 J = 1, N
         TH = TH + (H(J,J) + DIAG)
         DO 10 I = 1, N
            E(I) = 0.0D0
   10    CONTINUE
         E(J) = 1.0D0
         CALL QPCHSL (N, L, LDL, E, Y)
         TI = TI + Y(J)
   20 CONTINUE
      QPKAPP = TH*TI
      RETURN
      END
C
      SUBROUTINE QPLGN (N, NACT, GN, LDL, R, Y)                         ! D160
C     Y = Y - GN R OVER THE FIRST NACT COLUMNS OF GN
      INTEGER N, NACT, LDL, I, K                                        ! D160
      DOUBLE PRECISION GN(LDL,*), R(*), Y(*), S                         ! D160
      DO 20 I = 1, N                                                    ! D160
         S = Y(I)                                                       ! D160
         DO 10 K = 1, NACT                                              ! D160
            S = S - GN(I,K)*R(K)                                        ! D160
   10    CONTINUE                                                       ! D160
         Y(I) = S                                                       ! D160
   20 CONTINUE                                                          ! D160
      RETURN                                                            ! D160
      END                                                               ! D160
C
      SUBROUTINE QPHV (N, H, LDH, X, Y)                                 ! D160
C     Y = H X, H READ FROM ITS LOWER TRIANGLE (THE PART QPROG READS)
      INTEGER N, LDH, I, J                                              ! D160
      DOUBLE PRECISION H(LDH,*), X(*), Y(*), S                          ! D160
      DO 20 I = 1, N                                                    ! D160
         S = 0.0D0                                                      ! D160
         DO 10 J = 1, N                                                 ! D160
            IF (I.GE.J) S = S + H(I,J)*X(J)                             ! D160
            IF (I.LT.J) S = S + H(J,I)*X(J)                             ! D160
   10    CONTINUE                                                       ! D160
         Y(I) = S                                                       ! D160
   20 CONTINUE                                                          ! D160
      RETURN                                                            ! D160
      END                                                               ! D160
C
      DOUBLE PRECISION FUNCTION QPCOND (NVAR, NACT, IACT, SGN, A, LDA,  ! D160
     *                 H, LDH, L, LDL, GN, M, MC, LDM, RHS, R, Y, E)    ! D160
C     D160: TRACE(H) * TRACE(P H P), P = (H+DIAG I)^-1 - GN M^-1 GN' THE
C     INVERSE OF H + DIAG I ON THE DIRECTIONS THE ACTIVE ROWS LEAVE FREE
C     (GN = (H+DIAG I)^-1 N, M = N'GN, N THE ACTIVE NORMALS).  A DIRECTION
C     OF H'S OF EIGENVALUE LAMBDA COUNTS LAMBDA/(LAMBDA+DIAG)**2: 1/LAMBDA
C     WHERE H DETERMINES IT, NOTHING ON H'S NULL DIRECTIONS (WHICH DIAG
C     DECIDES) NOR ON THOSE THE ACTIVE ROWS PIN.  IT BOUNDS THE RELATIVE
C     CHANGE OF SOL PER RELATIVE CHANGE OF H, ON THE DIRECTIONS H
C     DETERMINES; WITH DIAG = 0 AND NO ACTIVE ROW, TR(H) TR(H^-1).  WHERE
C     M IS SINGULAR (NUMERICALLY DEPENDENT ACTIVE ROWS) P = (H+DIAG I)^-1.
C     MC, RHS, R, Y, E: WORK.  FREE OF H'S UNITS AND OF THE ROWS' SCALES.
      INTEGER NVAR, NACT, IACT(*), LDA, LDH, LDL, LDM, I, J, K, INFO    ! D160
      DOUBLE PRECISION SGN(*), A(LDA,*), H(LDH,*), L(LDL,*), GN(LDL,*), ! D160
     *                 M(LDM,*), MC(LDM,*), RHS(*), R(*), Y(*), E(*),   ! D160
     *                 TH, TR                                           ! D160
      LOGICAL PROJ                                                      ! D160
      CALL QPNMAT (NVAR, NACT, IACT, SGN, A, LDA, L, LDL, GN, MC, LDM,  ! D160
     *             E)                                                   ! D160
      PROJ = NACT.GT.0                                                  ! D160
      TH = 0.0D0                                                        ! D160
      TR = 0.0D0                                                        ! D160
      DO 60 J = 1, NVAR                                                 ! D160
         TH = TH + H(J,J)                                               ! D160
         DO 10 I = 1, NVAR                                              ! D160
            E(I) = 0.0D0                                                ! D160
   10    CONTINUE                                                       ! D160
         E(J) = 1.0D0                                                   ! D160
         CALL QPCHSL (NVAR, L, LDL, E, Y)                               ! D160
         IF (PROJ) THEN                                                 ! D160
            DO 20 K = 1, NACT                                           ! D160
               RHS(K) = GN(J,K)                                         ! D160
               DO 15 I = 1, NACT                                        ! D160
                  M(I,K) = MC(I,K)                                      ! D160
   15          CONTINUE                                                 ! D160
   20       CONTINUE                                                    ! D160
            CALL QPGAUS (NACT, M, LDM, RHS, R, INFO)                    ! D160
            PROJ = INFO.EQ.0                                            ! D160
         END IF                                                         ! D160
         IF (PROJ) CALL QPLGN (NVAR, NACT, GN, LDL, R, Y)               ! D160
         CALL QPHV (NVAR, H, LDH, Y, E)                                 ! D160
         DO 50 I = 1, NVAR                                              ! D160
            TR = TR + Y(I)*E(I)                                         ! D160
   50    CONTINUE                                                       ! D160
   60 CONTINUE                                                          ! D160
      QPCOND = TH*TR                                                    ! D160
      RETURN                                                            ! D160
      END                                                               ! D160
C
      LOGICAL FUNCTION QPUNBD (NVAR, NCON, NEQ, A, LDA, G, H, LDH, L,   ! D163
     *                         LDL, SGN, IACT, NACT, SOL, GN, M, LDM,   ! D163
     *                         RHS, R, D, E)                            ! D163
C     D163: IS THE PROBLEM UNBOUNDED BELOW?  SOL IS A REGULARIZED
C     ANSWER, OF THE PROBLEM OR OF ITS RECESSION PROBLEM (B = 0, WHOSE
C     ANSWER DOES NOT DEPEND ON B'S SCALE): FAR OUT ALONG H'S NULL
C     DIRECTIONS IF THE OBJECTIVE FALLS ALONG A FEASIBLE ONE.  TWO
C     DIRECTIONS FROM IT, EACH DAMPING H'S RANGE BY DIAG/(LAMBDA+DIAG):
C     D = P SOL, P = (H+DIAG I)^-1 - GN M^-1 GN' THE INVERSE ON THE
C     DIRECTIONS THE ACTIVE ROWS LEAVE FREE (AS QPCOND), WHICH LEAVES
C     THOSE ROWS WHERE THEY ARE; AND D = SOL - (H+DIAG I)^-1 H SOL, WHICH
C     MAY LEAVE AN ACTIVE INEQUALITY (AS A DIRECTION OF NEGATIVE
C     CURVATURE DOES).  EITHER CERTIFIES IT (QPRAY).  GN, M, RHS, R, D,
C     E: WORK.
      INTEGER NVAR, NCON, NEQ, LDA, LDH, LDL, LDM, IACT(*), NACT, J, K, ! D163
     *        INFO                                                      ! D163
      DOUBLE PRECISION A(LDA,*), G(*), H(LDH,*), L(LDL,*), SGN(*),      ! D163
     *                 SOL(*), GN(LDL,*), M(LDM,*), RHS(*), R(*), D(*), ! D163
     *                 E(*), S                                          ! D163
      LOGICAL FREE, QPRAY                                               ! D163
      QPUNBD = .TRUE.                                                   ! D163
      CALL QPCHSL (NVAR, L, LDL, SOL, D)                                ! D163
      FREE = .TRUE.                                                     ! D163
      IF (NACT.GT.0) THEN                                               ! D163
         CALL QPNMAT (NVAR, NACT, IACT, SGN, A, LDA, L, LDL, GN, M, LDM,! D163
     *                E)                                                ! D163
         DO 5 K = 1, NACT                                               ! D163
            S = 0.0D0                                                   ! D163
            DO 4 J = 1, NVAR                                            ! D163
               S = S + GN(J,K)*SOL(J)                                   ! D163
    4       CONTINUE                                                    ! D163
            RHS(K) = S                                                  ! D163
    5    CONTINUE                                                       ! D163
         CALL QPGAUS (NACT, M, LDM, RHS, R, INFO)                       ! D163
         FREE = INFO.EQ.0                                               ! D163
         IF (FREE) CALL QPLGN (NVAR, NACT, GN, LDL, R, D)               ! D163
      END IF                                                            ! D163
      IF (FREE) THEN                                                    ! D163
         IF (QPRAY(NVAR, NCON, NEQ, A, LDA, G, H, LDH, D, E)) RETURN    ! D163
      END IF                                                            ! D163
      CALL QPHV (NVAR, H, LDH, SOL, E)                                  ! D163
      CALL QPCHSL (NVAR, L, LDL, E, D)                                  ! D163
      DO 9 J = 1, NVAR                                                  ! D163
         D(J) = SOL(J) - D(J)                                           ! D163
    9 CONTINUE                                                          ! D163
      QPUNBD = QPRAY(NVAR, NCON, NEQ, A, LDA, G, H, LDH, D, E)          ! D163
      RETURN                                                            ! D163
      END                                                               ! D163
C
      LOGICAL FUNCTION QPRAY (NVAR, NCON, NEQ, A, LDA, G, H, LDH, D, E) ! D163
C     D163: DOES D CERTIFY THAT THE PROBLEM IS UNBOUNDED BELOW?  EVERY
C     ROW STAYS FEASIBLE ALONG D (A(I,.)D = 0 FOR AN EQUALITY, >= 0 FOR AN
C     INEQUALITY), AND THE OBJECTIVE FALLS WITHOUT BOUND ALONG IT: H D = 0
C     AND G'D < 0, OR D'H D < 0.  EACH TO TAU = SQRT(EPS) OF THE
C     PROBLEM'S SCALE ALONG D, D TAKEN TO MAX|D(J)| = 1 FIRST (A(I,.)D OF
C     SUM |A(I,J)|, G'D OF SUM |G(J)|, H D OF MAX|H(I,J)|, D'H D OF
C     MAX|H(I,J)| D'D): THE DIAG RULE'S OWN LEVEL, WHICH TAKES A
C     CURVATURE BELOW IT FOR NONE.  E: WORK.
      INTEGER NVAR, NCON, NEQ, LDA, LDH, I, J                           ! D163
      DOUBLE PRECISION A(LDA,*), G(*), H(LDH,*), D(*), E(*), TAU, HMAX, ! D163
     *                 DMAX, DD, CURV, GD, GS, S, SIZE, QPHMAX          ! D163
      LOGICAL FLAT                                                      ! D163
      QPRAY = .FALSE.                                                   ! D163
      TAU = SQRT(EPSILON(1.0D0))                                        ! D163
      DMAX = 0.0D0                                                      ! D163
      DO 5 J = 1, NVAR                                                  ! D163
         DMAX = MAX(DMAX, ABS(D(J)))                                    ! D163
    5 CONTINUE                                                          ! D163
      IF (DMAX.EQ.0.0D0) RETURN                                         ! D163
      DD = 0.0D0                                                        ! D163
      GD = 0.0D0                                                        ! D163
      GS = 0.0D0                                                        ! D163
      DO 10 J = 1, NVAR                                                 ! D163
         D(J) = D(J)/DMAX                                               ! D163
         DD = DD + D(J)*D(J)                                            ! D163
         GD = GD + G(J)*D(J)                                            ! D163
         GS = GS + ABS(G(J))                                            ! D163
   10 CONTINUE                                                          ! D163
      HMAX = QPHMAX(NVAR, H, LDH)                                       ! D163
      CALL QPHV (NVAR, H, LDH, D, E)                                    ! D163
      FLAT = .TRUE.                                                     ! D163
      CURV = 0.0D0                                                      ! D163
      DO 20 I = 1, NVAR                                                 ! D163
         IF (ABS(E(I)).GT.TAU*HMAX) FLAT = .FALSE.                      ! D163
         CURV = CURV + D(I)*E(I)                                        ! D163
   20 CONTINUE                                                          ! D163
      IF (.NOT.((FLAT .AND. GD.LT.-TAU*GS) .OR.                         ! D163
     *          CURV.LT.-TAU*HMAX*DD)) RETURN                           ! D163
      DO 40 I = 1, NCON                                                 ! D163
         S = 0.0D0                                                      ! D163
         SIZE = 0.0D0                                                   ! D163
         DO 30 J = 1, NVAR                                              ! D163
            S = S + A(I,J)*D(J)                                         ! D163
            SIZE = SIZE + ABS(A(I,J))                                   ! D163
   30    CONTINUE                                                       ! D163
         IF (I.LE.NEQ) S = -ABS(S)                                      ! D163
         IF (S.LT.-TAU*SIZE) RETURN                                     ! D163
   40 CONTINUE                                                          ! D163
      QPRAY = .TRUE.                                                    ! D163
      RETURN                                                            ! D163
      END                                                               ! D163
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
      SUBROUTINE QPCOND_GET (QCOND_OUT)                                 ! D160
C     QCOND OF THE LAST SOLVED CALL (FOR THE PYTHON FACE; QPCOND)
      DOUBLE PRECISION QCOND_OUT, QCOND                                 ! D160
      COMMON /QPCND/ QCOND                                              ! D160
      QCOND_OUT = QCOND                                                 ! D160
      RETURN                                                            ! D160
      END                                                               ! D160
C
      SUBROUTINE QPWARN_GET (NWARN_OUT, WERR_OUT, RESET)                ! D161
C     HOW MANY REAL*4 QPROG CALLS SINCE THE LAST RESET SINGLE PRECISION
C     COULD NOT CARRY, AND THE WORST RELATIVE ERROR; RESET <> 0 CLEARS
      INTEGER NWARN_OUT, RESET, NWARN                                   ! D161
      DOUBLE PRECISION WERR_OUT, WERR                                   ! D161
      COMMON /QPWARN/ WERR, NWARN                                       ! D161
      NWARN_OUT = NWARN                                                 ! D161
      WERR_OUT = WERR                                                   ! D161
      IF (RESET.NE.0) THEN                                              ! D161
         NWARN = 0                                                      ! D161
         WERR = 0.0D0                                                   ! D161
      END IF                                                            ! D161
      RETURN                                                            ! D161
      END                                                               ! D161
C
      SUBROUTINE UMACH (N, NUNIT)
C     IMSL UMACH: N=1 STANDARD INPUT UNIT, N=2 STANDARD OUTPUT UNIT.
      INTEGER N, NUNIT
      NUNIT = 6
      IF (N.EQ.1 .OR. N.EQ.-1) NUNIT = 5
      RETURN
      END
