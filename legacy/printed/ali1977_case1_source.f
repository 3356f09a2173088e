C     $JOB TIME=15,NOSUBCHK
C *****************************************************************
C *                                                               *
C *   K.E.D. ANALYSIS OF THE SOURCE FOUR-BAR MECHANISM.           *
C *                                                               *
C *****************************************************************
C *                                                               *
C * THIS PROCEDURE COMPUTES THE DEFLECTIONS AT THE COUPLER POINT. *
C * THE MASS OF THE FOUR-BAR IS ASSUMED TO BE NEGLIGIBLE COMPARED TO
C * THE INERTIAL MASS AT THE COUPLER POINT.                       *
C * THE MASS 'M'=2 POUNDS IS LOCATED AT THE POINT 'P'.            *
C *                                                               *
C *****************************************************************
C *                                                               *
C --- THE FOLLOWING ARE THE DIMENSIONS OF THE FOUR-BAR:---
C *                                                               *
C *L1---- THE INPUT LINK LENGTH OF THE SOURCE FOUR-BAR MECHANISM.  *
C *L2---- THE COUPLER EXTENDER LENGTH ATTACHED RIGIDLY TO COUPLER.*
C *L3---- THE COUPLER LINK LENGTH OF THE SOURCE FOUR-BAR MECHANISM.
C *L4---- THE OUT PUT LINK LENGTH OF THE SOURCE FOUR-BAR MECHANISM.
C *L5---- THE FIXED LINK LENGTH OF THE SOURCE FOUR-BAR MECHANISM.  *
C *                                                               *
C *ALP---- THE RIGID ANGLE BETWEEN THE COUPLER AND EXTENDER.       *
C *T2---- THE INPUT ANGLE IN RADIAN.                               *
C *T3---- THE COUPLER ANGLE IN RADIAN.                             *
C *T4---- THE OUT-PUT ANGLE IN RADIAN.                             *
C *OM2---- THE ANGULAR VELOCITY OF THE INPUT LINK IN RAD/SEC.      *
C *OM3---- THE ANGULAR VELOCITY OF THE COUPLER IN RADIAN/SEC.      *
C *OM4---- THE ANGULAR VELOCITY OF THE OUTPUT LINK IN RADIAN/SEC.  *
C *ALPH2---- THE ANGULAR ACC. OF INPUT IS CONSIDERED AS ZERO.      *
C *ALPH3---- THE ANGULAR ACC. OF THE COUPLER LINK IN RAD/SEC/SEC.  *
C *ALPH4---- THE ANGULAR ACC. OF THE OUTPUT LINK IN RAD/SEC/SEC.   *
C *XPA---- THE HORIZONTAL COMPONENT OF ACC. OF THE PT."P".         *
C *YPA---- THE VERTICAL COMPONENT OF THE ACC. OF PT."P".           *
C *XPF---- THE HORIZONTAL COMP. OF THE FORCE AT THE PT."P".        *
C *YPF---- THE VERTICAL COMP. OF THE FORCE AT THE PT."P".          *
C *                                                               *
C *****************************************************************
C *                                                               *
C *THE FOLLOWING DATA MUST BE SUPPLIED TO THE PROGRAM
C *
C *1. THE LINK LENGTHS: L1,L2,L3,L4,L5
C *2. THE ANGULAR VELOCITY OF THE INPUT LINK "OM2"
C *3. THE ANGULAR ACCELERATION OF THE INPUT LINK "ALPH2"
C *4. THE CROSS-SECTIONAL AREA OF THE LINKS "CA"
C *5. THE CROSS-SECTIONAL MOMENT OF INERTIA "MI"
C *6. THE MODULUS OF ELASTICITY OF THE LINK MATERIAL "ME"
C *
C *NOTE: THE LINK LENGTH L2 IS THE COUPLER EXTENDER
C *-----
C *NOTE: THE SUBROUTINES GMTRA&MPRD ARE TO BE EXTERNALLY SUPPLIED.
C *-----
C *
      DOUBLE PRECISION L1,L2,L3,L4,L5,K1,K2,K3,K4,K5,DCOS,DSIN,DATAN,
     *AA,BB,CC,DD,EE,FF,A1,B1,C1,D1,E1,F1,G1,H1,I1,R1,CX,SX,CTX,DSQRT,
     *T2,T3,T4,ALP,CA,MI,ME,OM2,OM3,OM4,AJ,BJ,CJ,DJ,EJ,FJ,ALPH2,ALPH3,
     *ALPH4,DCOT,PI,XP,YP,XX,YY,NXP,NYP
      DIMENSION A(64),B(64),R(64),S(37,2),Q(37,2)
      L1=10.0
      L2=10.0
      L3=30.0
      L4=25.0
      L5=30.0
      K1=L5/L1
      K2=L5/L4
      K3=(L1*L1-L3*L3+L4*L4+L5*L5)/(2.0*L1*L4)
      K4=L5/L3
      K5=(L4*L4-L5*L5-L1*L1-L3*L3)/(2.0*L1*L3)
      PI=3.142857143
C  N---- THE SPEED OF ROTATION OF THE INPUT LINK.
      N=400.0
      OM2=(2.0*PI*N)/60.0
      WRITE(6,100)
  100 FORMAT (1H1,9X,' DEGREES',13X,' X-DISP. OF P',3X,' Y-DISP. OF P',
     *10X,' Z-ROT. OF P')
      P2=-10.0
    5 P2=P2+10.0
      T2=(P2*2.0*PI)/(360.0)
      AA=DCOS(T2)+K3-K1-(K2*DCOS(T2))
      BB=-2.0*DSIN(T2)
      CC=K1+K3-(1.0+K2)*DCOS(T2)
      DD=(K4*DCOS(T2))+DCOS(T2)+K5-K1
      EE=-2.0*DSIN(T2)
      FF=(K4*DCOS(T2))-DCOS(T2)+K5+K1
      T3=2.0*(DATAN((-EE-DSQRT(EE*EE-4.0*DD*FF))/(2.0*DD)))
      T4=2.0*(DATAN((-BB-DSQRT(BB*BB-4.0*AA*CC))/(2.0*AA)))
      CX=DCOS(T4-T3)
      SX=DSIN(T4-T3)
      CTX=CX/SX
      ALP=1.762782545
      XP=(L1*DCOS(T2))+(L2*DCOS(ALP+T3))
      YP=(L1*DSIN(T2))+(L2*DSIN(ALP+T3))
      OM3=(L1*OM2*DSIN(T4-T3))/(L3*DSIN(T3-T4))
      OM4=(L1*OM2*DSIN(T2-T3))/(L4*DSIN(T4-T3))
      AJ=L4*DSIN(T4)
      BJ=L3*DSIN(T3)
      CJ=(L1*OM2*OM2*DCOS(T2))+(L3*OM3*OM3*DCOS(T3))-(L4*OM4*OM4*DCOS(T4
     *))
      DJ=L4*DCOS(T4)
      EJ=L3*DCOS(T3)
      FJ=(L4*OM4*OM4*DSIN(T4))-(L1*OM2*OM2*DSIN(T2))-(L3*OM3*OM3*DSIN(T3
     *))
      ALPH2=0.0
      ALPH3=(CJ*DJ-AJ*FJ)/(AJ*EJ-BJ*DJ)
      ALPH4=(CJ*EJ-BJ*FJ)/(AJ*EJ-BJ*DJ)
      XPA=-(L1*OM2*OM2*DCOS(T2))-(L1*ALPH2*DSIN(T2))-(L2*OM3*OM3*DCOS(
     *ALP+T3))-(L2*ALPH3*DSIN(ALP+T3))
      YPA=(L1*ALPH2*DCOS(T2))-(L1*OM2*OM2*DSIN(T2))+(L2*ALPH3*DCOS(ALP+
     *T3))-(L2*OM3*OM3*DSIN(ALP+T3))
      XPF=XPA*2.0/(12.0*32.178)
      YPF=YPA*2.0/(12.0*32.178)
      A1=DCOS(T2)
      B1=-DSIN(T2)
      C1=DCOS(T4)
      D1=DSIN(T2)
      E1=DCOS(T2)
      F1=DSIN(T4)
      G1=-(L2*DCOS(ALP+T3)*DCOS(T2))+(L2*DSIN(ALP+T3)*DCOS(T2))
      H1=-(L2*DCOS(ALP+T3)*DCOS(T2))-(L2*DSIN(ALP+T3)*DSIN(T2))
      I1=DSIN(T4)*((L2*DCOS(T3))-(L2*DCOS(ALP+T3)))+DCOS(T4)*((L2*DSIN(
     #ALP+T3))-(L3*DSIN(T3)))
      R1=(A1*(E1*I1-F1*H1))-(B1*(D1*I1-F1*G1))+(C1*(D1*H1-E1*G1))
C THE FORCE TRANSFORMATION MATRIX.
      A(1)=DCOS(T3+ALP)
      A(2)=-DSIN(T3+ALP)
      A(3)=0.0
      A(4)=((E1*I1)-(F1*H1))/R1
      A(5)=((F1*G1)-(D1*I1))/R1
      A(6)=((D1*H1)-(E1*G1))/R1
      A(7)=CTX*DSIN(T3+ALP)*(L2/L3)
      A(8)=-DSIN(T3+ALP)*L2
      A(9)=DSIN(T3+ALP)
      A(10)=DCOS(T3+ALP)
      A(11)=0.0
      A(12)=((C1*H1-B1*I1))/R1
      A(13)=((A1*I1)-(C1*G1))/R1
      A(14)=((B1*G1)-(A1*H1))/R1
      A(15)=-DCOS(T3+ALP)*CTX*(L2/L3)
      A(16)=DCOS(T3+ALP)*L2
      A(17)=0.0
      A(18)=0.0
      A(19)=1.0
      A(20)=((B1*F1)-(C1*E1))/R1
      A(21)=((C1*D1)-(A1*F1))/R1
      A(22)=((A1*E1)-(B1*D1))/R1
      A(23)=-CTX/L3
      A(24)=1.0
      N=8
      M=3
C *TRANSPOSING THE FORCE TRANSFORMATION MATRIX(BETA).
      CALL GMTRA(A,R,N,M)
C *TRANSPOSED FORCE TRANSFER MATRIX IS MULTIPLIED BY FLEXIBILITY MAT*
C *RIX AND THE RESULT IS STORED IN R.
      DO 55 I=1,24
   55 A(I)=R(I)
C
C *ALL LINKS ARE OF UNIFORM CIRCULAR CROSS-SECTION OF DIA.=0.5 IN. *
C
C *"CA"-CROSS-SECTIONAL AREA OF ALL LINKS. *
C
      CA=0.1963495408
C
C *"ME"-YOUNG'S MODULUS OF ELASTICITY FOR THE MATERIAL ALUMINIUM. *
C
      ME=10000000.0
C
C *"MI"-CROSS-SECTIONAL MOMENT OF INERTIA. *
C
      MI=0.0030679615
C *THE FLEXIBILITY MATRIX"(F)". *
      B(1)=L2/(CA*ME)
      DO 10 I=2,9
   10 B(I)=0.0
      B(10)=(L2*L2*L2)/(3.0*ME*MI)
      B(11)=(L2*L2)/(2.0*ME*MI)
      DO 11 I=12,17
   11 B(I)=0.0
      B(18)=(L2*L2)/(2.0*ME*MI)
      B(19)=L2/(ME*MI)
      DO 12 I=20,27
   12 B(I)=0.0
      B(28)=L1/(CA*ME)
      DO 13 I=29,36
   13 B(I)=0.0
      B(37)=(L1*L1*L1)/(3.0*CA*ME)
      DO 14 I=38,45
   14 B(I)=0.0
      B(46)=L4/(CA*ME)
      DO 15 I=47,54
   15 B(I)=0.0
      B(55)=L3/(CA*ME)
      DO 16 I=56,63
   16 B(I)=0.0
      B(64)=L3/(3.0*ME*MI)
      N=3
      M=8
      MSA=0
      MSB=0
      L=8
      CALL MPRD(A,B,R,N,M,MSA,MSB,L)
C
C *THE PRODUCT R IS MULTIPLIED BY THE FORCE TRANSFER MATRIX.      *
      DO 66 I=1,24
   66 A(I)=R(I)
C
C *THE FORCE TRANSFER MATRIX
C
      B(1)=DCOS(T3+ALP)
      B(2)=-DSIN(T3+ALP)
      B(3)=0.0
      B(4)=((E1*I1)-(F1*H1))/R1
      B(5)=((F1*G1)-(D1*I1))/R1
      B(6)=((D1*H1)-(E1*G1))/R1
      B(7)=CTX*DSIN(T3+ALP)*(L2/L3)
      B(8)=-(DSIN(T3+ALP))*L2
      B(9)=DSIN(T3+ALP)
      B(10)=DCOS(T3+ALP)
      B(11)=0.0
      B(12)=((C1*H1)-(B1*I1))/R1
      B(13)=((A1*I1)-(C1*G1))/R1
      B(14)=((B1*G1)-(A1*H1))/R1
      B(15)=-(DCOS(T3+ALP))*CTX*(L2/L3)
      B(16)=DCOS(T3+ALP)*L2
      B(17)=0.0
      B(18)=0.0
      B(19)=1.0
      B(20)=((B1*F1)-(C1*E1))/R1
      B(21)=((C1*D1)-(A1*F1))/R1
      B(22)=((A1*E1)-(B1*D1))/R1
      B(23)=-CTX/L3
      B(24)=1.0
      N=3
      M=8
      MSA=0
      MSB=0
      L=5
      CALL MPRD(A,B,R,N,M,MSA,MSB,L)
      DO 77 I=1,9
   77 A(I)=R(I)
      B(1)=XPF
      B(2)=YPF
      B(3)=0.0
      N=3
      M=3
      MSA=0
      MSB=0
      L=1
      CALL MPRD(A,B,R,N,N,MSA,MSB,L)
      XX=R(1)
      YY=R(2)
      RT=R(3)
      IF (P2.EQ.360.0) GO TO 999
      WRITE (6,200)P2,XX,YY,RT
  200 FORMAT(1H0,5X,F12.6,8X,F12.6,8X,F12.6,8X,F12.6)
      GO TO 5
  999 STOP
      END
