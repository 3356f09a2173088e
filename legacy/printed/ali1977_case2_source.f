C     $JOB TIME=55,NOSUBCHK,LIBLIST
C *****************************************************************
C
C *****************************************************************
C *                                                               *
C *   [LINKREPRO] CASE II SOURCE FOUR-BAR (APPENDIX C, FIRST      *
C *   LISTING). THE TEXT OF THIS COMMENT BOX IS NOT LEGIBLE IN THE *
C *   SCAN (SEED LINES 1672-1687 SHOW ONLY ITS FRAME).             *
C *                                                               *
C *****************************************************************
C *
C *
C *
C *
C *
C *****************************************************************
C *****************************************************************
      DOUBLE PRECISION L1,L2,L3,L4,L5,K1,K2,K3,K4,K5,DCOS,DSIN,DATAN,
     *AA,BB,CC,DD,EE,FF,A1,B1,C1,D1,E1,F1,G1,H1,I1,R1,CX,SX,CTX,DSQRT,
     *T2,T3,T4,ALP,CA,MI,ME,OM2,OM3,OM4,AJ,BJ,CJ,DJ,EJ,FJ,ALPH2,ALPH3,
     *ALPH4,DCOT,PI,XP,YP,XX,YY,NXP,NYP
     *,DNTY,VOL1,VOL2,VOL3,VOL4,XAA,XBA,YAA,YBA,M1,M2,M3,M4
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
C
C SPEED ---- THE SPEED OF THE INPUT LINK IN R.P.M.
C
      SPEED=300.0
      OM2=(2.0*PI*SPEED)/60.0
      WRITE(6,100)
  100 FORMAT(1H1,9X,'DEGREES',13X,'X-DISP. OF P',3X,'Y-DISP. OF P',10X,
     *'Z-RT OF P')
      P2=-10.0
    5 P2=P2+10.0
      T2=(P2*2.0*PI)/(360.0)
      AA=DCOS(T2)+K3-K1-(K2*DCOS(T2))
      BB=-2.0*DSIN(T2)
      CC=K1+K3-(1.0+K2)*DCOS(T2)
      DD=(K4*DCOS(T2))+DCOS(T2)+K5-K1
      EE=-2.0*DSIN(T2)
      FF=(K4*DCOS(T2))-DCOS(T2)+K5+K1
      T3=2.0*DATAN((-EE-DSQRT(EE*EE-4.0*DD*FF))/(2.0*DD))
      T4=2.0*DATAN((-BB-DSQRT(BB*BB-4.0*AA*CC))/(2.0*AA))
      CX=DCOS(T4-T3)
      SX=DSIN(T4-T3)
      CTX=CX/SX
      ALP=PI/3.0
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
      XAA=-(L1*DSIN(T2)*ALPH2)-(L1*DCOS(T2)*OM2*OM2)
      YAA=(L1*DCOS(T2)*ALPH2)-(L1*DSIN(T2)*OM2*OM2)
      XBA=-(L1*ALPH2*DSIN(T2))-(L1*OM2*OM2*DCOS(T2))-(L3*OM3*OM3*DCOS(T3
     *))+(L3*ALPH3*DSIN(T3))
      YBA=-(L1*OM2*OM2*DSIN(T2))+(L1*ALPH2*DCOS(T2))-(L3*OM3*OM3*DSIN(T3
     *))+(L3*ALPH3*DCOS(T3))
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
C
C DENSITY OF ALUMINIUM = 0.098.
C
      DNTY=0.098
      GC=32.178*12.0
      VOL1=CA*L1
      VOL2=CA*L2
      VOL3=CA*L3
      VOL4=CA*L4
      M1=DNTY*VOL1
      M2=DNTY*VOL2
      M3=DNTY*VOL3
      M4=DNTY*VOL4
      P1=(M2*XPA)/(32.178*12.0)
      Z2=(M2*YPA)/(32.178*12.0)
      P3=0.0
      P4=(M1*(XAA*DCOS(T2)+YAA*DSIN(T2)))/GC
      P5=(M1*(YAA*DSIN(T2)-XAA*DCOS(T2)))/GC
      P6=(M4*(YBA*DSIN(T4)-XBA*DCOS(T4)))/GC
      P7=(M3*(YAA*DSIN(T3)-XAA*DCOS(T3)))/GC
      P8=0.0
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
C     THE FORCE TRANSFORMATION MATRIX.
      A(1)=DCOS(T3+ALP)
      A(2)=-DSIN(T3+ALP)
      A(3)=0.0
      A(4)=((E1*I1)-(F1*H1))/R1
      A(5)=((F1*G1)-(D1*I1))/R1
      A(6)=((D1*H1)-(E1*G1))/R1
      A(7)=CTX*DSIN(T3+ALP)*(L2/L3)
      A(8)=-(DSIN(T3+ALP))*L2
      A(9)=DSIN(T3+ALP)
      A(10)=DCOS(T3+ALP)
      A(11)=0.0
      A(12)=((C1*H1-B1*I1))/R1
      A(13)=((A1*I1)-(C1*G1))/R1
      A(14)=((B1*G1)-(A1*H1))/R1
      A(15)=-(DCOS(T3+ALP))*CTX*(L2/L3)
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
C     TRANSPOSING THE FORCE TRANSFORMATION MATRIX(BETA).
      CALL GMTRA(A,R,N,M)
C     TRANSPOSED FORCE TRANSFER MATRIX IS MULTIPLIED BY FLEXIBILITY MAT*
C     RIX AND THE RESULT IS STORED IN R.
      DO 55 I=1,24
   55 A(I)=R(I)
C     THE FLEXIBILITY MATRIX"(F)".
      B(1)=(L2/(CA*ME))
      B(2)=0.0
      B(3)=0.0
      B(4)=0.0
      B(5)=0.0
      B(6)=0.0
      B(7)=0.0
      B(8)=0.0
      B(9)=0.0
      B(10)=(L2*L2*L2)/(3.0*ME*MI)
      B(11)=(L2*L2)/(2.0*ME*MI)
      B(12)=0.0
      B(13)=0.0
      B(14)=0.0
      B(15)=0.0
      B(16)=0.0
      B(17)=0.0
      B(18)=(L2*L2)/(2.0*ME*MI)
      B(19)=L2/(ME*MI)
      B(20)=0.0
      B(21)=0.0
      B(22)=0.0
      B(23)=0.0
      B(24)=0.0
      B(25)=0.0
      B(26)=0.0
      B(27)=0.0
      B(28)=L1/(CA*ME)
      B(29)=0.0
      B(30)=0.0
      B(31)=0.0
      B(32)=0.0
      B(33)=0.0
      B(34)=0.0
      B(35)=0.0
      B(36)=0.0
      B(37)=(L1*L1*L1)/(3.0*CA*ME)
      B(38)=0.0
      B(39)=0.0
      B(40)=0.0
      B(41)=0.0
      B(42)=0.0
      B(43)=0.0
      B(44)=0.0
      B(45)=0.0
      B(46)=L4/(CA*ME)
      B(47)=0.0
      B(48)=0.0
      B(49)=0.0
      B(50)=0.0
      B(51)=0.0
      B(52)=0.0
      B(53)=0.0
      B(54)=0.0
      B(55)=L3/(CA*ME)
      B(56)=0.0
      B(57)=0.0
      B(58)=0.0
      B(59)=0.0
      B(60)=0.0
      B(61)=0.0
      B(62)=0.0
      B(63)=0.0
      B(64)=L3/(3.0*ME*MI)
      N=3
      M=8
      MSA=0
      MSB=0
      L=8
      CALL MPRD(A,B,R,N,M,MSA,MSB,L)
C
C     *THE PRODUCT R IS MULTIPLIED BY THE FORCE TRANSFER MATRIX.
      DO 66 I=1,24
   66 A(I)=R(I)
C
C     *THE FORCE TRANSFER MATRIX
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
      B(25)=B(3)
      B(26)=B(3)
      B(27)=B(3)
      B(28)=1.0
      B(29)=B(3)
      B(30)=B(3)
      B(31)=B(3)
      B(32)=B(3)
      B(33)=B(3)
      B(34)=B(3)
      B(35)=B(3)
      B(36)=B(3)
      B(37)=1.0
      B(38)=B(3)
      B(39)=B(3)
      B(40)=B(3)
      B(41)=B(3)
      B(42)=B(3)
      B(43)=B(3)
      B(44)=B(3)
      B(45)=B(3)
      B(46)=1.0
      B(47)=B(3)
      B(48)=B(3)
      B(49)=B(3)
      B(50)=B(3)
      B(51)=B(3)
      B(52)=-DCOS(T2-T3)
      B(53)=DSIN(T2-T3)
      B(54)=B(3)
      B(55)=1.0
      B(56)=B(3)
      B(57)=B(3)
      B(58)=B(3)
      B(59)=B(3)
      B(60)=B(3)
      B(61)=B(3)
      B(62)=B(3)
      B(63)=B(3)
      B(64)=1.0
      N=3
      M=8
      MSA=0
      MSB=0
      L=8
      CALL MPRD(A,B,R,N,M,MSA,MSB,L)
      DO 11 I=1,24
   11 A(I)=R(I)
C
C     THE SYSTEM FORCE MATRIX FOR THE SOURCE MECHANISM.
C
      B(1)=P1
      B(2)=Z2
      B(3)=P3
      B(4)=P4
      B(5)=P5
      B(6)=P6
      B(7)=P7
      B(8)=P8
      N=3
      M=8
      MSA=0
      MSB=0
      L=1
      CALL MPRD(A,B,R,N,M,MSA,MSB,L)
      XX=R(1)
      YY=R(2)
      RT=R(3)
      WRITE(6,200)P2,XX,YY,RT
  200 FORMAT(1H0,5X,F12.6,8X,F12.6,8X,F12.6,8X,F12.6)
      IF (P2.EQ.360.0) GO TO 6
      GO TO 5
    6 STOP
      END
