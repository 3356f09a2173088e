C *****
      DOUBLE PRECISION L1,L2,L3,L4,L5,K1,K2,K3,K4,K5,DCOS,DSIN,DATAN,
     *AA,BB,CC,DD,EE,FF,A1,B1,C1,D1,E1,F1,G1,H1,I1,R1,CX,SX,CTX,DSQRT,
     *T2,T3,T4,ALP,CA,MI,ME,OM2,OM3,OM4,AJ,BJ,CJ,DJ,EJ,FJ,ALPH2,ALPH3,
     *ALPH4,DCOT,PI,XP,YP,XX,YY,NXP,NYP
     *,DNTY,VOL1,VOL2,VOL3,VOL4,XAA,XBA,YAA,YBA,M1,M2,M3,M4
     *,G2,G3,G4,G5,H2,H3,H4,H5,I2,I3,I4,I5,R5,R2,R3,R4,L21,L22,L23,L24
     *,CI,CE
     *,P1,Z2,P3,P4,P5,P6,P7,P8,XPA1,YPA1,XPA2,YPA2,XPA3,YPA3,XPA4,YPA4,
     *XPA5,YPA5,M21,M22,M23,M24,GC
      DIMENSION A(1600),B(1600),R(1600),U(1600)
      L1=10.0
      L2=10.0
      L3=30.0
      L4=25.0
      L5=30.0
      K1=L5/L1
      K2=L5/L4
      K3=(L1*L1-L3*L3+L4*L4+L5*L5)/(2.0*L1*L4)
      CI=0.0030679615
      K4=L5/L3
      K5=(L4*L4-L5*L5-L1*L1-L3*L3)/(2.0*L1*L3)
      L21=L2-2.0
      L22=L2-4.0
      L23=L2-6.0
      L24=L2-8.0
      PI=3.142857143
C
C      S---- THE SPEED OF ROTATION OF THE INPUT LINK =300 R.P.M.
C
      S=300.0
      OM2=(2.0*PI*S)/60.0
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
      FJ=(L4*OM4*OM4*SIN(T4))-(L1*OM2*OM2*DSIN(T2))-(L3*OM3*OM3*DSIN(T3)
     *)
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
C     *ALL LINKS ARE OF UNIFORM CIRCULAR CROSS-SECTION OF DIA.=0.5 IN. *
C
C     *"CA"-CROSS-SECTIONAL AREA OF ALL LINKS. *
C
      CA=0.1963495408
C
C     *CE---- THE MODULUS OF ELASTICITY. *
C
      CE=10000000.0
C
C     *"MI"-CROSS-SECTIONAL MOMENT OF INERTIA. *
C
      MI=0.0030679615
      A1=DCOS(T2)
      B1=-DSIN(T2)
      C1=DCOS(T4)
      D1=DSIN(T2)
      E1=DCOS(T2)
      F1=DSIN(T4)
      G1=-(L2*DCOS(ALP+T3)*DCOS(T2))+(L2*DSIN(ALP+T3)*DCOS(T2))
      G2=-(L21*DCOS(ALP+T3)*DCOS(T2))+(L21*DSIN(ALP+T3)*DCOS(T2))
      G3=-(L22*DCOS(ALP+T3)*DCOS(T2))+(L22*DSIN(ALP+T3)*DCOS(T2))
      G4=-(L23*DCOS(ALP+T3)*DCOS(T2))+(L23*DSIN(ALP+T3)*DCOS(T2))
      G5=-(L24*DCOS(ALP+T3)*DCOS(T2))+(L24*DSIN(ALP+T3)*DCOS(T2))
      H1=-(L2*DCOS(ALP+T3)*DCOS(T2))-(L2*DSIN(ALP+T3)*DSIN(T2))
      H2=-(L21*DCOS(ALP+T3)*DCOS(T2))-(L21*DSIN(ALP+T3)*DSIN(T2))
      H3=-(L22*DCOS(ALP+T3)*DCOS(T2))-(L22*DSIN(ALP+T3)*DSIN(T2))
      H4=-(L23*DCOS(ALP+T3)*DCOS(T2))-(L23*DSIN(ALP+T3)*DSIN(T2))
      H5=-(L24*DCOS(ALP+T3)*DCOS(T2))-(L24*DSIN(ALP+T3)*DSIN(T2))
      I1=DSIN(T4)*((L3*DCOS(T3))-(L2*DCOS(ALP+T3)))+DCOS(T4)*((L2*DSIN(A
     *LP+T3))-(L3*DSIN(T3)))
      I2=DSIN(T4)*((L3*DCOS(T3))-(L21*DCOS(ALP+T3)))+DCOS(T4)*((L21*DSIN
     *(ALP+T3))-(L3*DSIN(T3)))
      I3=DSIN(T4)*((L3*DCOS(T3))-(L22*DCOS(ALP+T3)))+DCOS(T4)*((L22*DSIN
     *(ALP+T3))-(L3*DSIN(T3)))
      I4=DSIN(T4)*((L3*DCOS(T3))-(L23*DCOS(ALP+T3)))+DCOS(T4)*((L23*DSIN
     *(ALP+T3))-(L3*DSIN(T3)))
      I5=DSIN(T4)*((L3*DCOS(T3))-(L24*DCOS(ALP+T3)))+DCOS(T4)*((L24*DSIN
     *(ALP+T3))-(L3*DSIN(T3)))
      R1=(A1*(E1*I1-F1*H1))-(B1*(D1*I1-F1*G1))+(C1*(D1*H1-E1*G1))
      R2=(A1*(E1*I2-F1*H2))-(B1*(D1*I2-F1*G2))+(C1*(D1*H2-E1*G2))
      R3=(A1*(E1*I3-F1*H3))-(B1*(D1*I3-F1*G3))+(C1*(D1*H3-E1*G3))
      R4=(A1*(E1*I4-F1*H4))-(B1*(D1*I4-F1*G4))+(C1*(D1*H4-E1*G4))
      R5=(A1*(E1*I5-F1*H5))-(B1*(D1*I5-F1*G5))+(C1*(D1*H5-E1*G5))
      XPA1=-(L1*OM2*OM2*DCOS(T2))-(L1*ALPH2*DSIN(T2))-(L2*OM3*OM3*DCOS(A
     *LP+T3))-(L2*ALPH3*DSIN(ALP+T3))
      XPA2=-(L1*OM2*OM2*DCOS(T2))-(L1*ALPH2*DSIN(T2))-(L21*OM3*OM3*DCOS(
     *ALP+T3))-(L21*ALPH3*DSIN(ALP+T3))
      XPA3=-(L1*OM2*OM2*DCOS(T2))-(L1*ALPH2*DSIN(T2))-(L22*OM3*OM3*DCOS(
     *ALP+T3))-(L22*ALPH3*DSIN(ALP+T3))
      XPA4=-(L1*OM2*OM2*DCOS(T2))-(L1*ALPH2*DSIN(T2))-(L23*OM3*OM3*DCOS(
     *ALP+T3))-(L23*ALPH3*DSIN(ALP+T3))
      XPA5=-(L1*OM2*OM2*DCOS(T2))-(L1*ALPH2*DSIN(T2))-(L24*OM3*OM3*DCOS(
     *ALP+T3))-(L24*ALPH3*DSIN(ALP+T3))
      YPA1=(L1*ALPH2*DCOS(T2))-(L1*OM2*OM2*DSIN(T2))+(L2*ALPH3*DCOS(ALP+
     *T3))-(L2*OM3*OM3*DSIN(ALP+T3))
      YPA2=(L1*ALPH2*DCOS(T2))-(L1*OM2*OM2*DSIN(T2))+(L21*ALPH3*DCOS(ALP
     *+T3))-(L21*OM3*OM3*DSIN(ALP+T3))
      YPA3=(L1*ALPH2*DCOS(T2))-(L1*OM2*OM2*DSIN(T2))+(L22*ALPH3*DCOS(ALP
     *+T3))-(L22*OM3*OM3*DSIN(ALP+T3))
      YPA4=(L1*ALPH2*DCOS(T2))-(L1*OM2*OM2*DSIN(T2))+(L23*ALPH3*DCOS(ALP
     *+T3))-(L23*OM3*OM3*DSIN(ALP+T3))
      YPA5=(L1*ALPH2*DCOS(T2))-(L1*OM2*OM2*DSIN(T2))+(L24*ALPH3*DCOS(ALP
     *+T3))-(L24*OM3*OM3*DSIN(ALP+T3))
C
C      DENSITY OF ALUMINIUM IS 0.098 LB/CU.IN.
C
      DNTY=0.098
      VOL2=CA*L2
      VOL21=CA*L21
      VOL22=CA*L22
      VOL23=CA*L23
      VOL24=CA*L24
      M2=VOL2*DNTY
      M21=VOL21*DNTY
      M22=VOL22*DNTY
      M23=VOL23*DNTY
      M24=VOL24*DNTY
      GC=32.178*12.0
      P1=(XPA1*M2)/GC
      Z2=(YPA1*M2)/GC
      P3=0.0
      P4=(XPA2*M21)/GC
      P5=(YPA2*M21)/GC
      P6=0.0
      P7=(XPA3*M22)/GC
      P8=(YPA3*M22)/GC
      P9=0.0
      P10=(XPA4*M23)/GC
      P11=(YPA4*M23)/GC
      P12=0.0
      P13=(XPA5*M24)/GC
      P14=(YPA5*M24)/GC
      P15=0.0
C
C      THE FORCE TRANSFORMATION MATRIX FOR CASE NO.3*****
C
      U(1)=DCOS(T3+ALP)
      U(2)=-DSIN(T3+ALP)
      U(3)=0.0
      U(4)=((E1*I1)-(F1*H1))/R1
      U(5)=((F1*G1)-(D1*I1))/R1
      U(6)=((D1*H1)-(E1*G1))/R1
      U(7)=CTX*DSIN(T3+ALP)*L2/L3
      U(8)=-(DSIN(T3+ALP))*L2
      DO 50 I=9,40
   50 U(I)=0.0
      U(41)=DSIN(T3+ALP)
      U(42)=DCOS(T3+ALP)
      U(43)=0.0
      U(44)=(C1*H1-B1*I1)/R1
      U(45)=(A1*I1-C1*G1)/R1
      U(46)=(B1*G1-A1*H1)/R1
      U(47)=-(DCOS(T3+ALP))*CTX*(L2/L3)
      U(48)=DCOS(T3+ALP)*L2
      DO 51 I=49,90
   51 U(I)=0.0
      U(91)=1.0
      U(92)=(B1*F1-C1*E1)/R1
      U(93)=(C1*D1-A1*F1)/R1
      U(94)=(A1*E1-B1*D1)/R1
      U(95)=-CTX/L3
      U(96)=1.0
      DO 52 I=97,128
   52 U(I)=0.0
      U(129)=U(1)
      U(130)=U(2)
      U(131)=U(3)
      U(132)=(E1*I2-F1*H2)/R2
      U(133)=(F1*G2-D1*I2)/R2
      U(134)=(D1*H2-E1*G2)/R2
      U(135)=CTX*DSIN(T3+ALP)*L21/L3
      U(136)=-DSIN(T3+ALP)*L21
      DO 53 I=137,168
   53 U(I)=0.0
      U(169)=U(41)
      U(170)=U(42)
      U(171)=U(43)
      U(172)=(C1*H2-B1*I2)/R2
      U(173)=(A1*I2-C1*G2)/R2
      U(174)=(B1*G2-A1*H2)/R2
      U(175)=-(CTX*DCOS(T3+ALP))*L21/L3
      U(176)=DCOS(T3+ALP)*L21
      DO 54 I=177,210
   54 U(I)=0.0
      U(211)=1.0
      U(212)=(B1*F1-C1*E1)/R2
      U(213)=(C1*D1-A1*F1)/R2
      U(214)=(A1*E1-B1*D1)/R2
      U(215)=-CTX/L3
      U(216)=1.0
      DO 55 I=217,256
   55 U(I)=0.0
      U(257)=U(1)
      U(258)=U(2)
      U(259)=U(3)
      U(260)=(E1*I3-F1*H3)/R3
      U(261)=(F1*G3-D1*I3)/R3
      U(262)=(D1*H3-E1*G3)/R3
      U(263)=CTX*DSIN(T3+ALP)*L22/L3
      U(264)=-DSIN(T3+ALP)*L22
      DO 56 I=265,296
   56 U(I)=0.0
      U(297)=U(41)
      U(298)=U(42)
      U(299)=U(43)
      U(300)=(C1*H3-B1*I3)/R3
      U(301)=(A1*I3-C1*G3)/R3
      U(302)=(B1*G3-A1*H3)/R3
      U(303)=-(CTX*DCOS(ALP+T3)*L22)/L3
      U(304)=DCOS(T3+ALP)*L22
      DO 57 I=305,338
   57 U(I)=0.0
      U(339)=1.0
      U(340)=(B1*F1-C1*E1)/R3
      U(341)=(C1*D1-A1*F1)/R3
      U(342)=(A1*E1-B1*D1)/R3
      U(343)=-CTX/L3
      U(344)=1.0
      DO 58 I=345,384
   58 U(I)=0.0
      U(385)=U(1)
      U(386)=U(2)
      U(387)=U(3)
      U(388)=(E1*I4-F1*H4)/R4
      U(389)=(F1*G4-D1*I4)/R4
      U(390)=(D1*H4-E1*G4)/R4
      U(391)=CTX*DSIN(T3+ALP)*L23/L3
      U(392)=-DSIN(T3+ALP)*L23
      DO 59 I=393,424
   59 U(I)=0.0
      U(425)=U(41)
      U(426)=U(42)
      U(427)=U(43)
      U(428)=(C1*H4-B1*I4)/R4
      U(429)=(A1*I4-C1*G4)/R4
      U(430)=(B1*G4-A1*H4)/R4
      U(431)=-(CTX*DCOS(T3+ALP)*L23)/L3
      U(432)=DCOS(T3+ALP)*L23
      DO 60 I=433,466
   60 U(I)=0.0
      U(467)=1.0
      U(468)=(B1*F1-C1*E1)/R4
      U(469)=(C1*D1-A1*F1)/R4
      U(470)=(A1*D1-B1*I1)/R4
      U(471)=-CTX/L3
      U(472)=1.0
      DO 61 I=473,512
   61 U(I)=0.0
      U(513)=U(1)
      U(514)=U(2)
      U(515)=U(3)
      U(516)=(E1*I5-F1*H5)/R5
      U(517)=(F1*G5-D1*I5)/R5
      U(518)=(D1*H5-E1*G5)/R5
      U(519)=CTX*DSIN(T3+ALP)*L24/L3
      U(520)=-DSIN(T3+ALP)*L24
      DO 62 I=521,552
   62 U(I)=0.0
      U(553)=U(41)
      U(554)=U(42)
      U(555)=U(43)
      U(556)=(C1*H5-B1*I5)/R5
      U(557)=(A1*I5-C1*G5)/R5
      U(558)=(B1*G5-A1*H5)/R5
      U(559)=-(CTX*DCOS(ALP+T3)*L24)/L3
      U(560)=DCOS(T3+ALP)*L24
      DO 63 I=561,594
   63 U(I)=0.0
      U(595)=1.0
      U(596)=(B1*F1-C1*E1)/R5
      U(597)=(C1*D1-A1*F1)/R5
      U(598)=(A1*E1-B1*D1)/R5
      U(599)=-CTX/L3
      U(600)=1.0
      N=40
      M=15
C
C      FORCE TRANSFER MATRIX IS TRANSPOSED.
C
      CALL GMTRA(U,R,N,M)
      DO 100 I=1,600
  100 A(I)=R(I)
C
C      THE FORCE TRANSFER MATRIX IS MULTIPLIED BY FLEXIBILITY MATRIX.
C
      B(1)=L2/(CA*CE)
      DO 1 J=2,41
    1 B(J)=0.0
      B(42)=(L2*L2*L2)/(3.0*CE*CI)
      B(43)=(L2*L2)/(2.0*CE*CI)
      DO 2 J=44,81
    2 B(J)=0.0
      B(82)=(L2*L2)/(2.0*CE*CI)
      B(83)=L2/(CE*CI)
      DO 3 J=84,123
    3 B(J)=0.0
      B(124)=L1/(CA*CE)
      DO 4 J=125,164
    4 B(J)=0.0
      B(165)=(L1*L1*L1)/(3.0*CE*CI)
      DO 6 J=166,205
    6 B(J)=0.0
      B(206)=L4/(CA*CE)
      DO 7 J=207,246
    7 B(J)=0.0
      B(247)=L3/(CA*CE)
      DO 8 J=248,287
    8 B(J)=0.0
      B(288)=L3/(3.0*CE*CI)
      DO 9 J=289,328
    9 B(J)=0.0
      B(329)=L21/(CA*CE)
      DO 10 J=330,369
   10 B(J)=0.0
      B(370)=(L21*L21*L21)/(3.0*CE*CI)
      B(371)=(L21*L21)/(2.0*CE*CI)
      DO 11 J=372,409
   11 B(J)=0.0
      B(410)=(L21*L21)/(2.0*CE*CI)
      B(411)=L21/(CE*CI)
      DO 12 J=412,451
   12 B(J)=0.0
      B(452)=L1/(CA*CE)
      DO 13 J=453,492
   13 B(J)=0.0
      B(493)=(L1*L1*L1)/(3.0*CE*CI)
      DO 15 J=494,533
   15 B(J)=0.0
      B(534)=L4/(CA*CE)
      DO 16 J=535,574
   16 B(J)=0.0
      B(575)=L3/(CA*CE)
      DO 17 J=576,615
   17 B(J)=0.0
      B(616)=L3/(3.0*CE*CI)
      DO 18 J=617,656
   18 B(J)=0.0
      B(657)=L22/(CA*CE)
      DO 19 J=658,697
   19 B(J)=0.0
      B(698)=(L22*L22*L22)/(3.0*CE*CI)
      B(699)=(L22*L22)/(2.0*CE*CI)
      DO 20 J=700,737
   20 B(J)=0.0
      B(738)=(L22*L22)/(2.0*CE*CI)
      B(739)=L22/(CE*CI)
      DO 21 J=740,779
   21 B(J)=0.0
      B(780)=L1/(CA*CE)
      DO 22 J=781,820
   22 B(J)=0.0
      B(821)=(L1*L1*L1)/(3.0*CE*CI)
      DO 23 J=822,861
   23 B(J)=0.0
      B(862)=L4/(CA*CE)
      DO 24 J=863,902
   24 B(J)=0.0
      B(903)=L3/(CA*CE)
      DO 25 J=904,943
   25 B(J)=0.0
      B(944)=L3/(3.0*CE*CI)
      DO 26 J=945,984
   26 B(J)=0.0
      B(985)=L23/(CA*CE)
      DO 27 J=986,1025
   27 B(J)=0.0
      B(1026)=(L23*L23*L23)/(3.0*CE*CI)
      B(1027)=(L23*L23)/(2.0*CE*CI)
      DO 28 J=1028,1065
   28 B(J)=0.0
      B(1066)=(L23*L23)/(2.0*CE*CI)
      B(1067)=L23/(CE*CI)
      DO 29 J=1068,1107
   29 B(J)=0.0
      B(1108)=L1/(CA*CE)
      DO 30 J=1109,1148
   30 B(J)=0.0
      B(1149)=(L1*L1*L1)/(3.0*CE*CI)
      DO 31 J=1150,1189
   31 B(J)=0.0
      B(1190)=L4/(CA*CE)
      DO 32 J=1191,1230
   32 B(J)=0.0
      B(1231)=L3/(CA*CE)
      DO 33 J=1232,1271
   33 B(J)=0.0
      B(1272)=L3/(3.0*CE*CI)
      DO 34 J=1273,1312
   34 B(J)=0.0
      B(1313)=L24/(CA*CE)
      DO 35 J=1314,1353
   35 B(J)=0.0
      B(1354)=(L24*L24*L24)/(3.0*CE*CI)
      B(1355)=(L24*L24)/(2.0*CE*CI)
      DO 36 J=1356,1393
   36 B(J)=0.0
      B(1394)=(L24*L24)/(2.0*CE*CI)
      B(1395)=L24/(CE*CI)
      DO 37 J=1396,1435
   37 B(J)=0.0
      B(1436)=L1/(CA*CE)
      DO 38 J=1437,1476
   38 B(J)=0.0
      B(1477)=(L1*L1*L1)/(3.0*CE*CI)
      DO 39 J=1478,1517
   39 B(J)=0.0
      B(1518)=L4/(CA*CE)
      DO 40 J=1519,1558
   40 B(J)=0.0
      B(1559)=L3/(CA*CE)
      DO 41 J=1560,1599
   41 B(J)=0.0
      B(1600)=L3/(3.0*CE*CI)
      N=15
      M=40
      MSA=0
      MSB=0
      L=40
      CALL MPRD(A,B,R,N,M,MSA,MSB,L)
      DO 200 I=1,600
  200 A(I)=R(I)
C
C      THE RESULTANT IS MULTIPLIED BY THE FORCE TRANSFER MATRIX.
C
      U(1)=DCOS(T3+ALP)
      U(2)=-DSIN(T3+ALP)
      U(3)=0.0
      U(4)=((E1*I1)-(F1*H1))/R1
      U(5)=((F1*G1)-(D1*I1))/R1
      U(6)=((D1*H1)-(E1*G1))/R1
      U(7)=CTX*DSIN(T3+ALP)*(L2/L3)
      U(8)=-(DSIN(T3+ALP))*L2
      DO 70 I=9,40
   70 U(I)=0.0
      U(41)=DSIN(T3+ALP)
      U(42)=DCOS(T3+ALP)
      U(43)=0.0
      U(44)=(C1*H1-B1*I1)/R1
      U(45)=(A1*I1-C1*G1)/R1
      U(46)=(B1*G1-A1*H1)/R1
      U(47)=-(DCOS(T3+ALP))*CTX*(L2/L3)
      U(48)=DCOS(T3+ALP)*L2
      DO 71 I=49,90
   71 U(I)=0.0
      U(91)=1.0
      U(92)=(B1*F1-C1*E1)/R1
      U(93)=(C1*D1-A1*F1)/R1
      U(94)=(A1*E1-B1*D1)/R1
      U(95)=-CTX/L3
      U(96)=1.0
      DO 72 I=97,128
   72 U(I)=0.0
      U(129)=U(1)
      U(130)=U(2)
      U(131)=U(3)
      U(132)=(E1*I2-F1*H2)/R2
      U(133)=(F1*G2-D1*I2)/R2
      U(134)=(D1*H2-E1*G2)/R2
      U(135)=CTX*DSIN(T3+ALP)*L21/L3
      U(136)=-DSIN(T3+ALP)*L21
      DO 73 I=137,168
   73 U(I)=0.0
      U(169)=U(41)
      U(170)=U(42)
      U(171)=U(43)
      U(172)=(C1*H2-B1*I2)/R2
      U(173)=(A1*I2-C1*G2)/R2
      U(174)=(B1*G2-A1*H2)/R2
      U(175)=-(CTX*DCOS(T3+ALP))*L21/L3
      U(176)=DCOS(T3+ALP)*L21
      DO 74 I=177,210
   74 U(I)=0.0
      U(211)=1.0
      U(212)=(B1*F1-C1*E1)/R2
      U(213)=(C1*D1-A1*F1)/R2
      U(214)=(A1*E1-B1*D1)/R2
      U(215)=-CTX/L3
      U(216)=1.0
      DO 75 I=217,256
   75 U(I)=0.0
      U(257)=U(1)
      U(258)=U(2)
      U(259)=U(3)
      U(260)=(E1*I3-F1*H3)/R3
      U(261)=(F1*G3-D1*I3)/R3
      U(262)=(D1*H3-E1*G3)/R3
      U(263)=CTX*DSIN(T3+ALP)*L22/L3
      U(264)=-DSIN(T3+ALP)*L22
      DO 76 I=265,296
   76 U(I)=0.0
      U(297)=U(41)
      U(298)=U(42)
      U(299)=U(43)
      U(300)=(C1*H3-B1*I3)/R3
      U(301)=(A1*I3-C1*G3)/R3
      U(302)=(B1*G3-A1*H3)/R3
      U(303)=-(CTX*DCOS(ALP+T3)*L22)/L3
      U(304)=DCOS(T3+ALP)*L22
      DO 77 I=305,338
   77 U(I)=0.0
      U(339)=1.0
      U(340)=(B1*F1-C1*E1)/R3
      U(341)=(C1*D1-A1*F1)/R3
      U(342)=(A1*E1-B1*D1)/R3
      U(343)=-CTX/L3
      U(344)=1.0
      DO 78 I=345,384
   78 U(I)=0.0
      U(385)=U(1)
      U(386)=U(2)
      U(387)=U(3)
      U(388)=(E1*I4-F1*H4)/R4
      U(389)=(F1*G4-D1*I4)/R4
      U(390)=(D1*H4-E1*G4)/R4
      U(391)=CTX*DSIN(T3+ALP)*L23/L3
      U(392)=-DSIN(T3+ALP)*L23
      DO 79 I=393,424
   79 U(I)=0.0
      U(425)=U(41)
      U(426)=U(42)
      U(427)=U(43)
      U(428)=(C1*H4-B1*I4)/R4
      U(429)=(A1*I4-C1*G4)/R4
      U(430)=(B1*G4-A1*H4)/R4
      U(431)=-(CTX*DCOS(T3+ALP))*L23/L3
      U(432)=DCOS(T3+ALP)*L23
      DO 80 I=433,466
   80 U(I)=0.0
      U(467)=1.0
      U(468)=(B1*F1-C1*E1)/R4
      U(469)=(C1*D1-A1*F1)/R4
      U(470)=(A1*D1-B1*E1)/R4
      U(471)=-CTX/L3
      U(472)=1.0
      DO 81 I=473,512
   81 U(I)=0.0
      U(513)=U(1)
      U(514)=U(2)
      U(515)=U(3)
      U(516)=(E1*I5-F1*H5)/R5
      U(517)=(F1*G5-D1*I5)/R5
      U(518)=(D1*H5-E1*G5)/R5
      U(519)=CTX*DSIN(T3+ALP)*L24/L3
      U(520)=-DSIN(T3+ALP)*L24
      DO 82 I=521,552
   82 U(I)=0.0
      U(553)=U(41)
      U(554)=U(42)
      U(555)=U(43)
      U(556)=(C1*H5-B1*I5)/R5
      U(557)=(A1*I5-C1*G5)/R5
      U(558)=(B1*G5-A1*H5)/R5
      U(559)=-(CTX*DCOS(ALP+T3)*L24)/L3
      U(560)=DCOS(T3+ALP)*L24
      DO 83 I=561,594
   83 U(I)=0.0
      U(595)=1.0
      U(596)=(B1*F1-C1*E1)/R5
      U(597)=(C1*D1-A1*F1)/R5
      U(598)=(A1*E1-B1*D1)/R5
      U(599)=-CTX/L3
      U(600)=1.0
      N=15
      M=40
      MSA=0
      MSB=0
      L=15
      CALL MPRD(A,U,R,N,M,MSA,MSB,L)
      DO 300 I=1,225
  300 A(I)=R(I)
C
C      THE RESULTANT IS MULTIPLIED BY THE INERTIA MATRIX 'P'.
C
      B(1)=P1
      B(2)=Z2
      B(3)=P3
      B(4)=P4
      B(5)=P5
      B(6)=P6
      B(7)=P7
      B(8)=P8
      B(9)=P9
      B(10)=P10
      B(11)=P11
      B(12)=P12
      B(13)=P13
      B(14)=P14
      B(15)=P15
      CALL MPRD(A,B,R,N,M,MSA,MSB,L)
      N=15
      M=15
      MSA=0
      MSB=0
      L=1
      CALL MPRD(A,B,R,N,M,MSA,MSB,L)
      WRITE(6,500)P2,R(1),R(2),R(3),R(4),R(5),R(6),R(7),R(8),R(9),R(10),
     *R(11),R(12),R(13),R(14),R(15)
  500 FORMAT('1',F18.10,3(8X,F18.10)////'0',18X,3(8X,F18.10)////'0',18X,
     *3(8X,F18.10)////'0',18X,3(8X,F18.10)////'0',18X,3(8X,F18.10))
      IF(P2.GT.360.0) GO TO 999
      GO TO 5
  999 STOP
      END
