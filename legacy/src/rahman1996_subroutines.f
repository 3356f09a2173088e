      SUBROUTINE PRODUCTDUAL (AR,AD,BR,BD,RESLTR,RESLTD)
      real*8 AR(3,3),AD(3,3),BR(3,3),BD(3,3),TEMP1(3,3)
      real*8 RESLTR(3,3),RESLTD(3,3),TEMP2(3,3)
      CALL MULTI (AR,BR,RESLTR,3,3,3)
      CALL MULTI (AD,BR,TEMP1,3,3,3)
      CALL MULTI (AR,BD,TEMP2,3,3,3)
      CALL ADDMAT (TEMP1,TEMP2,RESLTD)
      RETURN
      END
C
      SUBROUTINE CORRLS (MTRX,MTRXD,MTRXDD,D,DD,DDD,
     1                   LL,L,LD,LDD)
      real*8 MTRX(3,3),MTRXD(3,3),MTRXDD(3,3),D(3),DD(3),
     1       DDD(3),LL(3),L(3),LD(3),LDD(3),
     1       TMTRX(3,3),TMTRXD(3,3),OMEGA(3,3),
     1       ALPHA1(3,3),ALPHA2(3,3),ALPHA(3,3),
     1       WX,WY,WZ,ALPX,ALPY,ALPZ,MTRXL(3),MTRXDL(3)
      CALL KINEMATIC (MTRX,MTRXD,MTRXDD,D,DD,DDD,
     1                LL,L,LD,LDD)
      CALL MULMAVEC (MTRX,LL,MTRXL,3,3)
      CALL MULMAVEC (MTRXD,LL,MTRXDL,3,3)
      CALL TRANS (MTRX,TMTRX,3,3)
      CALL TRANS (MTRXD,TMTRXD,3,3)
      CALL MULTI (MTRXD,TMTRX,OMEGA,3,3,3)
      CALL MULTI (MTRXDD,TMTRX,ALPHA1,3,3,3)
      CALL MULTI (MTRXD,TMTRXD,ALPHA2,3,3,3)
      CALL ADDMAT (ALPHA1,ALPHA2,ALPHA)
      WX=OMEGA(3,2)
      WY=OMEGA(1,3)
      WZ=OMEGA(2,1)
      ALPX=ALPHA(3,2)
      ALPY=ALPHA(1,3)
      ALPZ=ALPHA(2,1)
      LDD(1)=WY*(WX*MTRXL(2)-WY*MTRXL(1))
     1      -WZ*(WZ*MTRXL(1)-WX*MTRXL(3))
C    1      +2*WY*MTRXDL(3)-2*WZ*MTRXDL(2)
     1      +ALPY*MTRXL(3)-ALPZ*MTRXL(2)
     1      +DDD(1)
      LDD(2)=WZ*(WY*MTRXL(3)-WZ*MTRXL(2))
     1      -WX*(WX*MTRXL(2)-WY*MTRXL(1))
C    1      +2*WZ*MTRXDL(1)-2*WX*MTRXDL(3)
     1      +ALPZ*MTRXL(1)-ALPX*MTRXL(3)
     1      +DDD(2)
      LDD(3)=WX*(WZ*MTRXL(1)-WX*MTRXL(3))
     1      -WY*(WY*MTRXL(3)-WZ*MTRXL(2))
C    1      +2*WX*MTRXDL(2)-2*WY*MTRXDL(1)
     1      +ALPX*MTRXL(2)-ALPY*MTRXL(1)
     1      +DDD(3)
      RETURN
      END
C
      SUBROUTINE KINEMATIC (MTRX,MTRXD,MTRXDD,D,DD,DDD,
     1 LL,L,LD,LDD)
      real*8 MTRX(3,3),MTRXD(3,3),MTRXDD(3,3),D(3),DD(3),
     1       DDD(3),LL(3),L(3),LD(3),LDD(3),
     1       MTRXL(3),MTRXDL(3),MTRXDDL(3)
      CALL MULMAVEC (MTRX,LL,MTRXL,3,3)
      CALL ADDVEC (D,MTRXL,L)
      CALL MULMAVEC (MTRXD,LL,MTRXDL,3,3)
      CALL ADDVEC (DD,MTRXDL,LD)
      CALL MULMAVEC (MTRXDD,LL,MTRXDDL,3,3)
      CALL ADDVEC (DDD,MTRXDDL,LDD)
      RETURN
      END
      SUBROUTINE SQUARE (A,ASQ)
      real*8 A(9),ASQ(9,9)
      DO 10 I=1,9
      DO 20 J=1,9
      ASQ(I,J)=A(I)*A(J)
C     IF (I.NE. J) THEN
C     ASQ(I,J)=2*ASQ(I,J)
C     ENDIF
   20 CONTINUE
   10 CONTINUE
      RETURN
      END
C
      SUBROUTINE ADDMAT (A,B,C)
      real*8 A(3,3),B(3,3),C(3,3)
      DO 20 I=1,3
      DO 10 J=1,3
      C(I,J)=A(I,J)+B(I,J)
   10 CONTINUE
   20 CONTINUE
      RETURN
      END
C
      SUBROUTINE ADDVEC (A,B,C)
      REAL*8 A(3),B(3),C(3)
      DO 10 I=1,3
      C(I)=A(I)+B(I)
   10 CONTINUE
      RETURN
      END
C
      SUBROUTINE TRANSPOSE (AR,AD,TANSAR,TANSAD)
      real*8 AR(3,3),AD(3,3),TANSAR(3,3),TANSAD(3,3)
      CALL TRANS (AR,TANSAR,3,3)
      CALL TRANS (AD,TANSAD,3,3)
      RETURN
      END
C
      SUBROUTINE TRANS (A,AT,m,n)
      real*8 A(m,n),AT(n,m)
      DO 1, I=1,m
      DO 1, J=1,n
    1 AT(J,I)=A(I,J)
      RETURN
      END
C
      SUBROUTINE MULTI (A,B,C,l,m,n)
      real*8 A(l,n),B(n,m),C(l,m)
      DO 1, I=1,l
      DO 1, J=1,m
      C(I,J)=0.0
      DO 1, K=1,n
    1 C(I,J)=C(I,J)+A(I,K)*B(K,J)
      RETURN
      END
C
      SUBROUTINE MULMAVEC (A,B,C,l,m)
      real*8 A(l,m),B(m),C(l)
      DO 1, I=1,l
      C(I)=0.0
      DO 1, J=1,m
    1 C(I)=C(I)+A(I,J)*B(J)
      RETURN
      END
      subroutine dotprod(a,b,c)
      real*8 a(9),b(9),c
      c=0.0
      do 10 i=1,9
      c=c+a(i)*b(i)
   10 continue
      return
      end
C
      SUBROUTINE INVERSE (S,B)
      REAL*8 S(5,5),B(5,5),C(5,10)
      REAL*8 TEMP
      COMMON /INVERR/ IERINV                                            ! D052
      IERINV=0                                                          ! D052
C SPECIFICATION OF C MATRIX(AUGMENTED ATA MATRIX)
      DO 10 L=1,5
      DO 20 J=1,5
      C(L,J)=S(L,J)
   20 CONTINUE
   10 CONTINUE
      DO 11 I=1,5
      C(I,I+5)=1.0
   11 CONTINUE
C TO CHECK WHETHER PIVOT C(1,1) IS NONZERO
      IF (C(1,1).EQ.0.0000000)THEN
      DO 30 J=1,10
      TEMP=C(1,J)
      C(1,J)=C(2,J)
      C(2,J)=TEMP
   30 CONTINUE
      ELSE
      DO 61 I=2,5
      DO 71 J=2,5
      C(I,J)=C(I,J)-(C(I,1)*C(1,J)/C(1,1))
   71 CONTINUE
   61 CONTINUE
      GO TO 75
      END IF
      IF (C(1,1).EQ.0.0000000)THEN
      DO 31 J=1,10
      TEMP=C(1,J)
      C(1,J)=C(3,J)
      C(3,J)=TEMP
   31 CONTINUE
      ELSE
      DO 62 I=2,5
      DO 72 J=2,5
      C(I,J)=C(I,J)-(C(I,1)*C(1,J)/C(1,1))
   72 CONTINUE
   62 CONTINUE
      GO TO 75
      END IF
      IF (C(1,1).EQ.0.0000000)THEN
      DO 32 J=1,10
      TEMP=C(1,J)
      C(1,J)=C(4,J)
      C(4,J)=TEMP
   32 CONTINUE
      ELSE
      DO 63 I=2,5
      DO 73 J=2,5
      C(I,J)=C(I,J)-(C(I,1)*C(1,J)/C(1,1))
   73 CONTINUE
   63 CONTINUE
      GO TO 75
      END IF
      IF (C(1,1).EQ.0.0000000)THEN
      DO 33 J=1,10
      TEMP=C(1,J)
      C(1,J)=C(5,J)
      C(5,J)=TEMP
   33 CONTINUE
      ELSE
      DO 64 I=2,5
      DO 74 J=2,5
      C(I,J)=C(I,J)-(C(I,1)*C(1,J)/C(1,1))
   74 CONTINUE
   64 CONTINUE
      GO TO 75
      END IF
      IF (C(1,1).EQ.0.00000000)THEN
C     WRITE(6,*)'MATRIX IS SINGULAR'                                    ! D052
C     STOP                                                              ! D052
      IERINV=1                                                          ! D052
      RETURN                                                            ! D052
      ELSE
C DETERMINATION OF NEW C(I,J)
      DO 60 I=2,5
      DO 70 J=2,5
      C(I,J)=C(I,J)-(C(I,1)*C(1,J)/C(1,1))
   70 CONTINUE
   60 CONTINUE
      END IF
   75 C(2,6)=-C(2,1)/C(1,1)
      C(3,6)=-C(3,1)/C(1,1)
      C(4,6)=-C(4,1)/C(1,1)
      C(5,6)=-C(5,1)/C(1,1)
C TO CHECK PIVOT C(2,2)
      IF(C(2,2).EQ.0.0000000)THEN
      DO 100 J=2,10
      TEMP=C(2,J)
      C(2,J)=C(3,J)
      C(3,J)=TEMP
  100 CONTINUE
      ELSE
      DO 111 I=3,5
      DO 121 J=3,6
      C(I,J)=C(I,J)-(C(I,2)*C(2,J)/C(2,2))
  121 CONTINUE
  111 CONTINUE
      GO TO 114
      END IF
      IF( C(2,2).EQ.0.0000000)THEN
      DO 80 J=2,10
      TEMP=C(2,J)
      C(2,J)=C(4,J)
      C(4,J)=TEMP
   80 CONTINUE
      ELSE
      DO 112 I=3,5
      DO 122 J=3,6
      C(I,J)=C(I,J)-(C(I,2)*C(2,J)/C(2,2))
  122 CONTINUE
  112 CONTINUE
      GO TO 114
      END IF
      IF( C(2,2).EQ.0.0000000)THEN
      DO 90 J=2,10
      TEMP=C(2,J)
      C(2,J)=C(5,J)
      C(5,J)=TEMP
   90 CONTINUE
      ELSE
      DO 113 I=3,5
      DO 123 J=3,6
      C(I,J)=C(I,J)-(C(I,2)*C(2,J)/C(2,2))
  123 CONTINUE
  113 CONTINUE
      GO TO 114
      END IF
      IF( C(2,2).EQ.0.0000000)THEN
C     WRITE(6,*)'MATRIX IS SINGULAR'                                    ! D052
C     STOP                                                              ! D052
      IERINV=1                                                          ! D052
      RETURN                                                            ! D052
      ELSE
C DETERMINATION OF NEW C(I,J)
      DO 110 I=3,5
      DO 120 J=3,6
      C(I,J)=C(I,J)-(C(I,2)*C(2,J)/C(2,2))
  120 CONTINUE
  110 CONTINUE
      END IF
  114 C(3,7)=-C(3,2)/C(2,2)
      C(4,7)=-C(4,2)/C(2,2)
      C(5,7)=-C(5,2)/C(2,2)
C TO CHECK PIVOT C(3,3)
      IF (C(3,3).EQ.0.0000000)THEN
      DO 150 J=3,10
      TEMP=C(3,J)
      C(3,J)=C(4,J)
      C(4,J)=TEMP
  150 CONTINUE
      ELSE
      DO 161 I=4,5
      DO 171 J=4,7
      C(I,J)=C(I,J)-(C(I,3)*C(3,J)/C(3,3))
  171 CONTINUE
  161 CONTINUE
      GO TO 430
      END IF
      IF (C(3,3).EQ.0.0000000)THEN
      DO 130 J=3,10
      TEMP=C(3,J)
      C(3,J)=C(5,J)
      C(5,J)=TEMP
  130 CONTINUE
      ELSE
      DO 162 I=4,5
      DO 172 J=4,7
      C(I,J)=C(I,J)-(C(I,3)*C(3,J)/C(3,3))
  172 CONTINUE
  162 CONTINUE
      GO TO 430
      END IF
      IF (C(3,3).EQ.0.0000000)THEN
C     WRITE(6,*)'MATRIX IS SINGULAR'                                    ! D052
C     STOP                                                              ! D052
      IERINV=1                                                          ! D052
      RETURN                                                            ! D052
      ELSE
C DETERMINATION OF NEW C(I,J)
      DO 160 I=4,5
      DO 170 J=4,7
      C(I,J)=C(I,J)-(C(I,3)*C(3,J)/C(3,3))
  170 CONTINUE
  160 CONTINUE
      END IF
  430 C(4,8)=-C(4,3)/C(3,3)
      C(5,8)=-C(5,3)/C(3,3)
C TO CHECK PIVOT C(4,4)
      IF (C(4,4).EQ.0.0000000)THEN
      DO 200 J=4,10
      TEMP=C(4,J)
      C(4,J)=C(5,J)
      C(5,J)=TEMP
  200 CONTINUE
      ELSE
      DO 220 J=5,8
      C(5,J)=C(5,J)-(C(5,4)*C(4,J)/C(4,4))
  220 CONTINUE
      GO TO 190
      END IF
      IF (C(4,4).EQ.0.0000000)THEN
C     WRITE(6,*)'MATRIX IS SINGULAR'                                    ! D052
C     STOP                                                              ! D052
      IERINV=1                                                          ! D052
      RETURN                                                            ! D052
      ELSE
C DETERMINATION OF NEW C(I,J)
      DO 180 J=5,8
      C(5,J)=C(5,J)-(C(5,4)*C(4,J)/C(4,4))
  180 CONTINUE
      END IF
  190 C(5,9)=-C(5,4)/C(4,4)
C TO CHECK PIVOT C(5,5)
      IF (C(5,5).EQ.0.0000000)THEN
C     WRITE(6,*)'MATRIX IS SINGULAR'                                    ! D052
C     STOP                                                              ! D052
      IERINV=1                                                          ! D052
      RETURN                                                            ! D052
      ELSE
      C(5,10)=1.0
      C(4,10)=-C(4,5)/C(5,5)
      C(4,9)=1.0-(C(5,9)*C(4,5)/C(5,5))
      C(4,8)=C(4,8)-(C(5,8)*C(4,5)/C(5,5))
      C(4,7)=C(4,7)-(C(5,7)*C(4,5)/C(5,5))
      C(4,6)=C(4,6)-(C(5,6)*C(4,5)/C(5,5))
      C(3,10)=-C(3,5)/C(5,5)
      C(3,9)=-C(5,9)*C(3,5)/C(5,5)
      C(3,8)=1.0-(C(5,8)*C(3,5)/C(5,5))
      C(3,7)=C(3,7)-(C(5,7)*C(3,5)/C(5,5))
      C(3,6)=C(3,6)-(C(5,6)*C(3,5)/C(5,5))
      C(2,10)=-C(2,5)/C(5,5)
      C(2,9)=-C(5,9)*C(2,5)/C(5,5)
      C(2,8)=-C(5,8)*C(2,5)/C(5,5)
      C(2,7)=1.0-(C(5,7)*C(2,5)/C(5,5))
      C(2,6)=C(2,6)-(C(5,6)*C(2,5)/C(5,5))
      C(1,10)=-C(1,5)/C(5,5)
      C(1,9)=-C(5,9)*C(1,5)/C(5,5)
      C(1,8)=-C(5,8)*C(1,5)/C(5,5)
      C(1,7)=-C(5,7)*C(1,5)/C(5,5)
      C(1,6)=1.0-(C(5,6)*C(1,5)/C(5,5))
      DO 250 I=3,1,-1
      DO 260 J=5,10
      C(I,J)=C(I,J)-(C(I,4)*C(4,J)/C(4,4))
  260 CONTINUE
  250 CONTINUE
      DO 270 I=2,1,-1
      DO 280 J=4,10
      C(I,J)=C(I,J)-(C(I,3)*C(3,J)/C(3,3))
  280 CONTINUE
  270 CONTINUE
      DO 300 J=3,10
      C(1,J)=C(1,J)-(C(1,2)*C(2,J)/C(2,2))
  300 CONTINUE
C TO DETERMINE ELEMENTS OF B
      DO 310 I=1,5
      DO 320 J=1,5
      B(I,J)=C(I,J+5)/C(I,I)
  320 CONTINUE
  310 CONTINUE
      END IF
      RETURN
      END
C                                                                       ! D052
      SUBROUTINE INVERR_GET(IERR)                                       ! D052
C     THE SINGULAR FLAG OF THE LAST INVERSE CALL (FOR THE PYTHON FACE). ! D052
      COMMON /INVERR/ IERINV                                            ! D052
      IERR=IERINV                                                       ! D052
      RETURN                                                            ! D052
      END                                                               ! D052
