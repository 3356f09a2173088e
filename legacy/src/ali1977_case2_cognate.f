C     $JOB TIME=55,NOSUBCHK,LIBLIST
C *****************************************************************
C *
C *
C *          CASE II
C *          -----
C *
C *
C *****COUPLER- COGNATE MECHANISM*****
C *
C *          OF
C *
C *          FOUR-LINK MECHANISM
C *
C *****************************************************************
      SUBROUTINE KED2C(L1,L2,L3,L4,L5,ALP,SPEED,DNTY,CCA,CME,CMI,DSTEP,  ! D040
     *NANG,DEG,XPO,YPO,CXPO,CYPO,CXXO,CYYO,CRTO,ISTAT)                   ! D040
      DOUBLE PRECISION L1,CL1,L2,CL2,L3,CL3,L4,CL4,L5,CL5,K1,CK1,K2,CK2,
     *K3,CK3,K4,CK4,K5,CK5,AA,CAA,BB,CBB,CC,CCC,DD,CDD,EE,CEE,FF,CFF,T2,
     *T3,CT3,T4,CT4,OM2,COM2,OM3,COM3,OM4,COM4,AJ,CAJ,BJ,CBJ,CJ,CCJ,DJ,C
     *DJ,EJ,CEJ,FJ,CFJ,ALP,CALP,ALPH2,CALPH2,ALPH3,CALPH3,ALPH4,CALPH4,D
     *COS,DSIN,DATAN,DSQRT,DCOT,CX,CCX,SX,CSX,CTX,CCTX,A1,CA1,B1,CB1,C1,
     *CC1,D1,CD1,E1,CE1,F1,CF1,G1,CG1,H1,CH1,I1,CI1,R1,CR1,PI,CA,CCA,MI,
     *CMI,ME,CME,XP,CXP,YP,CYP,XX,CXX,YY,CYY,NXP,NCXP,NYP,NCYP,
     *XPP,YPP,BETA,Z1,Z2,K,CBTA,SBTA,TBTA,
     *DCXX,RLXX,TCPPX,TCPPY
      DIMENSION A(64),B(64),R(64),U(64),F(64)
      DOUBLE PRECISION SPEED,DEG(NANG),XPO(NANG),YPO(NANG),CXPO(NANG),   ! D041
     *CYPO(NANG),CXXO(NANG),CYYO(NANG),CRTO(NANG)                        ! D041
      DOUBLE PRECISION DNTY,CM1,CM2,CM3,CM4,CXAA,CYAA,CXBA,CYBA          ! D037
C     L1=10.0                                                            ! D040
C     L2=10.0                                                            ! D040
C     L3=30.0                                                            ! D040
C     L4=25.0                                                            ! D040
C     L5=30.0                                                            ! D040
      K1=L5/L1
      K2=L5/L4
      K3=(L1*L1-L3*L3+L4*L4+L5*L5)/(2.0*L1*L4)
      K4=L5/L3
      K5=(L4*L4-L5*L5-L1*L1-L3*L3)/(2.0*L1*L3)
C     WRITE(6,100)                                                       ! D041
  100 FORMAT(1H1,9X,'DEGREES',13X,'X-DISP.OF P',8X,'Y-DISP.OF P',10X,'Z-
     *ROT.OF P')
      PI=3.142857143
C
C     S---- THE SPEED OF ROTATION OF THE INPUT LINK =300 R.P.M.
C
      S=SPEED                                                            ! D040
      OM2=(2.0*PI*S)/60.0
      P2=-DSTEP                                                          ! D040
      IANG=0                                                             ! D041
      ISTAT=0                                                            ! D042
    5 P2=P2+DSTEP                                                        ! D040
      IANG=IANG+1                                                        ! D041
      DEG(IANG)=P2                                                       ! D041
      T2=(P2*2.0*PI)/(360.0)
      AA=DCOS(T2)+K3-K1-(K2*DCOS(T2))
      BB=-2.0*DSIN(T2)
      CC=K1+K3-(1.0+K2)*DCOS(T2)
      DD=(K4*DCOS(T2))+DCOS(T2)+K5-K1
      EE=-2.0*DSIN(T2)
      FF=(K4*DCOS(T2))-DCOS(T2)+K5+K1
      IF (EE*EE-4.0*DD*FF.LT.0.0.OR.BB*BB-4.0*AA*CC.LT.0.0) GO TO 998    ! D042
      T3=2.0*(DATAN((-EE-DSQRT(EE*EE-4.0*DD*FF))/(2.0*DD)))
      T4=2.0*(DATAN((-BB-DSQRT(BB*BB-4.0*AA*CC))/(2.0*AA)))
C     ALP=PI/3.0                                                         ! D040
      XP=(L1*DCOS(T2))+(L2*DCOS(ALP+T3))
      YP=(L1*DSIN(T2))+(L2*DSIN(ALP+T3))
C     *THE COUPLER COGNATE DIMENSIONS ARE AS FOLLOWS:-
C
      K=L2/L3
      CL4=DSQRT((L2*L2)+(L3*L3)-(2.0*L2*L3*DCOS(ALP)))
      CL3=L4*CL4/L3
      CL2=K*L4
      CL5=DSQRT(((K*L5)**2)+(L5*L5)-(2.0*L5*L5*K*DCOS(ALP)))
      CL1=L1*CL4/L3
      CBTA=((L3*L3)+(CL4*CL4)-(L2*L2))/(2.0*L3*CL4)
      SBTA=DSQRT(1.0-(CBTA)**2)
      TBTA=SBTA/CBTA
      BETA=ATAN(TBTA)
      CALP=PI-(BETA+ALP)
      CK1=CL5/CL1
      CK2=-CL5/CL4
      CK3=(CL3*CL3-CL1*CL1-CL4*CL4-CL5*CL5)/(2.0*CL1*CL4)
      CK4=-CL5/CL3
      CK5=(CL1*CL1+CL3*CL3+CL5*CL5-CL4*CL4)/(2.0*CL1*CL3)
      CAA=DCOS(T2)+CK3-CK1-(CK2*DCOS(T2))
      CBB=-2.0*DSIN(T2)
      CCC=CK1+CK3-(1.0+CK2)*DCOS(T2)
      CDD=(CK4*DCOS(T2))+DCOS(T2)+CK5-CK1
      CEE=-2.0*DSIN(T2)
      CFF=(CK4*DCOS(T2))-DCOS(T2)+CK5+CK1
      IF (CEE*CEE-4.0*CDD*CFF.LT.0.0) GO TO 998                          ! D042
      IF (CBB*CBB-4.0*CAA*CCC.LT.0.0) GO TO 998                          ! D042
      CT3=2.0*(ATAN((-CEE-DSQRT(CEE*CEE-4.0*CDD*CFF))/(2.0*CDD)))
      CT4=2.0*(ATAN((-CBB-DSQRT(CBB*CBB-4.0*CAA*CCC))/(2.0*CAA)))
      XPP=(CL1*DCOS(T2))+(CL2*DCOS(PI-(CALP-CT3)))
      YPP=(CL1*DSIN(T2))+(CL2*DSIN(PI-(CALP-CT3)))
      COM2=(2.0*PI*S)/60.0
      CALPH2=0.0
      COM3=(CL1*COM2*DSIN(T2-CT4))/(CL3*DSIN(CT3-CT4))
      COM4=(CL1*COM2*DSIN(CT3-T2))/(CL4*DSIN(CT4-CT3))
      CAJ=CL4*DSIN(CT4)
      CBJ=CL3*DSIN(CT3)
      CCJ=-(CL1*CALPH2*DSIN(T2))-(CL1*COM2*COM2*DCOS(T2))+(CL3*COM3*COM3
     **DCOS(CT3))-(CL4*COM4*COM4*DCOS(CT4))
      CDJ=CL4*DCOS(CT4)
      CEJ=CL3*DCOS(CT3)
      CFJ=-(CL1*CALPH2*DCOS(T2))+(CL1*COM2*COM2*DSIN(T2))-(CL3*COM3*COM3
     **DSIN(CT3))+(CL4*COM4*COM4*DSIN(CT4))
      CALPH3=(CCJ*CDJ-CAJ*CFJ)/(CAJ*CEJ-CBJ*CDJ)
      CALPH4=(CCJ*CEJ-CBJ*CFJ)/(CAJ*CEJ-CBJ*CDJ)
      CXPA=-(CL1*COM2*COM2*DCOS(T2))-(CL1*CALPH2*DSIN(T2))+(CL2*COM3*COM
     *3*DCOS(CALP-CT3))-(CL2*CALPH3*DSIN(CALP-CT3))
      CYPA=-(CL1*COM2*COM2*DSIN(T2))+(CL1*CALPH2*DCOS(T2))-(CL2*COM3*COM
     *3*DSIN(CALP-CT3))-(CL2*CALPH3*DCOS(CALP-CT3))
      CXPF=CXPA*2.0/(12.0*32.178)
      CYPF=CYPA*2.0/(12.0*32.178)
      CA1=-DCOS(T2)
      CB1=DSIN(T2)
      CC1=DCOS(CT4)
      CD1=-DSIN(T2)
      CE1=-DCOS(T2)
      CF1=DSIN(CT4)
      CG1=(CL2*DCOS(T2)*DSIN(CALP-CT3))+(CL2*DSIN(T2)*DCOS(CALP-CT3))
      CH1=(CL2*DCOS(T2)*DCOS(CALP-CT3))-(CL2*DSIN(T2)*DSIN(CALP-CT3))
      CI1=(CL2*DCOS(T2)*DSIN(CALP-CT3))+(CL3*DCOS(CT3)*DCOS(CT4))+(CL2*D
     *SIN(CT4)*DCOS(CALP-CT3))+(CL3*DSIN(CT4)*DSIN(CT3))
      CR1=(CA1*((CE1*CI1)-(CF1*CH1)))-(CB1*((CD1*CI1)-(CF1*CG1)))+(CC1*(
     *(CD1*CH1)-(CE1*CG1)))
      CCX=DCOS(CT3-CT4)
      CSX=DSIN(CT3-CT4)
      CCTX=CCX/CSX
C
C
C     THE FORCE TRANSFORMATION MATRIX FOR THE COGNATE FOR CASE#2.
C
      U(1)=-DCOS(CALP-CT3)
      U(2)=-DSIN(CALP-CT3)
      U(3)=0.0
      U(4)=(CE1*CI1-CF1*CH1)/CR1
      U(5)=(CF1*CG1-CD1*CI1)/CR1
      U(6)=(CD1*CH1-CE1*CG1)/CR1
      U(7)=-(CCTX*DSIN(CALP-CT3)*CL2/CL3)
      U(8)=-DSIN(CALP-CT3)*CL2
      U(9)=DSIN(CALP-CT3)
      U(10)=-DCOS(CALP-CT3)
      U(11)=0.0
      U(12)=(CC1*CH1-CB1*CI1)/CR1
      U(13)=(CA1*CI1-CC1*CG1)/CR1
      U(14)=(CB1*CG1-CA1*CH1)/CR1
      U(15)=-(DCOS(CALP-CT3)*CCTX*CL2/CL3)
      U(16)=-DCOS(CALP-CT3)*CL2
      U(17)=0.0
      U(18)=0.0
      U(19)=1.0
      U(20)=(CB1*CF1-CC1*CE1)/CR1
      U(21)=(CC1*CD1-CA1*CF1)/CR1
      U(22)=(CA1*CE1-CB1*CD1)/CR1
      U(23)=CCTX/CL3
      U(24)=1.0
C     TRANSPOSING THE FORCE TRANSFER MATRIX (CBETA) OF THE COGNATE.
C
      N=8
      M=3
      CALL GMTRA(U,R,N,M)
C
C     THE TRANSPOSED FORCE-TRANSFER MATRIX IS MULTIPLIED BY THE
C     COGNATE FLEXIBILITY MATRIX .
C
      DO 88 I=1,24
   88 A(I)=R(I)
C
C     *ALL LINKS ARE OF UNIFORM CROSS-SECTION OF DIA.=0.5".
C
C     *'CCA'--CROSS-SECTIONAL AREA OF ALL LINKS.
C     CCA=0.1963495408                                                   ! D040
C     *'CME'--YOUNG'S MODULUS OF ELASTICITY FOR MATERIAL ALUMINIUM.
C     CME=10000000.0                                                     ! D040
C     *'CMI'--CROSS-SECTIONAL MOMENT OF INERTIA.
C     CMI=0.0030679615                                                   ! D040
C     THE FLEXIBILITY MATRIX FOR THE COGNATE MECHANISM 'CF'.
C
      F(1)=CL2/(CCA*CME)
      F(2)=0.0
      F(3)=F(2)
      F(4)=F(2)
      F(5)=F(2)
      F(6)=F(2)
      F(7)=F(2)
      F(8)=F(2)
      F(9)=F(2)
      F(10)=(CL2*CL2*CL2)/(3.0*CME*CMI)
      F(11)=(CL2*CL2)/(2.0*CME*CMI)
      F(12)=F(2)
      F(13)=F(2)
      F(14)=F(2)
      F(15)=F(2)
      F(16)=F(2)
      F(17)=F(2)
      F(18)=(CL2*CL2)/(2.0*CME*CMI)
      F(19)=CL2/(CME*CMI)
      F(20)=F(2)
      F(21)=F(2)
      F(22)=F(2)
      F(23)=F(2)
      F(24)=F(2)
      F(25)=F(2)
      F(26)=F(2)
      F(27)=F(2)
      F(28)=CL1/(CCA*CME)
      F(29)=F(2)
      F(30)=F(2)
      F(31)=F(2)
      F(32)=F(2)
      F(33)=F(2)
      F(34)=F(2)
      F(35)=F(2)
      F(36)=F(2)
      F(37)=(CL1*CL1*CL1)/(3.0*CCA*CME)
      F(38)=F(2)
      F(39)=F(2)
      F(40)=F(2)
      F(41)=F(2)
      F(42)=F(2)
      F(43)=F(2)
      F(44)=F(2)
      F(45)=F(2)
      F(46)=CL4/(CCA*CME)
      F(47)=F(2)
      F(48)=F(2)
      F(49)=F(2)
      F(50)=F(2)
      F(51)=F(2)
      F(52)=F(2)
      F(53)=F(2)
      F(54)=F(2)
      F(55)=CL3/(CCA*CME)
      F(56)=F(2)
      F(57)=F(2)
      F(58)=F(2)
      F(59)=F(2)
      F(60)=F(2)
      F(61)=F(2)
      F(62)=F(2)
      F(63)=F(2)
      F(64)=CL3/(3.0*CME*CMI)
      N=3
      M=8
      MSA=0
      MSB=0
      L=8
      CALL MPRD(A,F,R,N,M,MSA,MSB,L)
C
C     THE PRODUCT R IS MULTIPLIED BY THE FORCE-TRANSFER MATRIX.
C
      DO 99 I=1,24
   99 A(I)=R(I)
C     THE FORCE TRANSFER MATRIX FOR COGNATE FOR CASE#2.
      U(1)=-DCOS(CALP-CT3)
      U(2)=-DSIN(CALP-CT3)
      U(3)=0.0
      U(4)=(CE1*CI1-CF1*CH1)/CR1
      U(5)=(CF1*CG1-CD1*CI1)/CR1
      U(6)=(CD1*CH1-CE1*CG1)/CR1
      U(7)=-((CCTX*DSIN(CALP-CT3))*CL2/CL3)
      U(8)=-DSIN(CALP-CT3)*CL2
      U(9)=DSIN(CALP-CT3)
      U(10)=-DCOS(CALP-CT3)
      U(11)=0.0
      U(12)=(CC1*CH1-CB1*CI1)/CR1
      U(13)=(CA1*CI1-CC1*CG1)/CR1
      U(14)=(CB1*CG1-CA1*CH1)/CR1
      U(15)=-((DCOS(CALP-CT3))*CCTX*CL2/CL3)
      U(16)=-DCOS(CALP-CT3)*CL2
      U(17)=0.0
      U(18)=0.0
      U(19)=1.0
      U(20)=(CB1*CF1-CC1*CE1)/CR1
      U(21)=(CC1*CD1-CA1*CF1)/CR1
      U(22)=(CA1*CE1-CB1*CD1)/CR1
      U(23)=CCTX/CL3
      U(24)=1.0
      DO 90 I=25,27
   90 U(I)=0.0
      U(28)=1.0
      DO 91 I=29,36
   91 U(I)=0.0
      U(37)=1.0
      DO 92 I=38,45
   92 U(I)=0.0
      U(46)=1.0
      DO 93 I=47,51
   93 U(I)=0.0
      U(52)=DCOS(CT3-T2)
      U(53)=DSIN(CT3-T2)
      U(54)=0.0
      U(55)=1.0
      DO 94 I=56,63
   94 U(I)=0.0
      U(64)=1.0
      N=3
      M=8
      MSA=0
      MSB=0
      L=8
      CALL MPRD(A,U,R,N,M,MSA,MSB,L)
      DO 111 I=1,24
  111 A(I)=R(I)
C     [LINKREPRO] RECONSTRUCTION OF THE MISSING STATEMENTS 241-281: THE  ! D037
C     CASE II SOURCE LISTING'S LOADS (ITS STATEMENTS 55-72) AND LAST     ! D037
C     PRODUCT (258-277) WRITTEN FOR THE COGNATE'S LINKS AND JOINTS.      ! D037
C     P7 ALONG THE COGNATE'S COUPLER AXIS -E3 (B'=A'-CL3*E3), THE AXIS   ! D037
C     OF THE PRINTED PAGE'S U(52), U(53).                                ! D037
      GC=32.178*12.0                                                     ! D037
      CM1=DNTY*(CCA*CL1)                                                 ! D037
      CM2=DNTY*(CCA*CL2)                                                 ! D037
      CM3=DNTY*(CCA*CL3)                                                 ! D037
      CM4=DNTY*(CCA*CL4)                                                 ! D037
      CXAA=-(CL1*DCOS(T2)*COM2*COM2)                                     ! D037
      CYAA=-(CL1*DSIN(T2)*COM2*COM2)                                     ! D037
      CXBA=CXAA+(CL3*COM3*COM3*DCOS(CT3))+(CL3*CALPH3*DSIN(CT3))         ! D037
      CYBA=CYAA+(CL3*COM3*COM3*DSIN(CT3))-(CL3*CALPH3*DCOS(CT3))         ! D037
      P1=(CM2*CXPA)/(32.178*12.0)                                        ! D037
      Z2=(CM2*CYPA)/(32.178*12.0)                                        ! D037
      P3=0.0                                                             ! D037
      P4=(CM1*(CXAA*DCOS(T2)+CYAA*DSIN(T2)))/GC                          ! D037
      P5=(CM1*(CYAA*DSIN(T2)-CXAA*DCOS(T2)))/GC                          ! D037
      P6=(CM4*(CYBA*DSIN(CT4)-CXBA*DCOS(CT4)))/GC                        ! D037
      P7=(CM3*(CXAA*DCOS(CT3)-CYAA*DSIN(CT3)))/GC                        ! D037
      P8=0.0                                                             ! D037
      B(1)=P1                                                            ! D037
      B(2)=Z2                                                            ! D037
      B(3)=P3                                                            ! D037
      B(4)=P4                                                            ! D037
      B(5)=P5                                                            ! D037
      B(6)=P6                                                            ! D037
      B(7)=P7                                                            ! D037
      B(8)=P8                                                            ! D037
      N=3                                                                ! D037
      M=8                                                                ! D037
      MSA=0                                                              ! D037
      MSB=0                                                              ! D037
      L=1                                                                ! D037
      CALL MPRD(A,B,R,N,M,MSA,MSB,L)                                     ! D037
      CXX=R(1)                                                           ! D037
      CYY=R(2)                                                           ! D037
      CRT=R(3)                                                           ! D037
C *****************************************************************
C     [LINKREPRO] STATEMENTS 241-281 ARE MISSING FROM THE SCAN (SEED
C     LINE 2555: A PAGE OF THE LISTING IS ABSENT; THE TEXT JUMPS FROM
C     STATEMENT 240 TO STATEMENT 282). THEY ARE NOT RECONSTRUCTED.
C     CXX, CYY AND CRT, USED BELOW, ARE SET ONLY IN THE MISSING PART
C     (IN THE CASE I COGNATE LISTING THEY ARE CXX=R(1), CYY=R(2),
C     CRT=R(3) AFTER THE PRODUCT WITH THE LOAD VECTOR); HERE THEY ARE
C     NEVER ASSIGNED, SO THE VALUES WRITTEN FOR THEM ARE UNDEFINED.
C *****************************************************************
C
      XDP=XPP-CL5
      XRP=(XDP*DCOS(-BETA))-(YPP*DSIN(-BETA))
      CXP=XRP+L5
      CYP=(XDP*DSIN(-BETA))+(YPP*DCOS(-BETA))
      NCXP=CXP+CXX
      NCYP=CYP+CYY
C     [LINKREPRO] STATEMENTS 288-289 ARE BLANK IN THE SCAN (SEED LINES
C     2569-2570: ONLY THEIR SEQUENCE NUMBERS ARE PRINTED). NOT
C     RECONSTRUCTED.
      XPO(IANG)=XP                                                       ! D041
      YPO(IANG)=YP                                                       ! D041
      CXPO(IANG)=CXP                                                     ! D041
      CYPO(IANG)=CYP                                                     ! D041
      CXXO(IANG)=CXX                                                     ! D041
      CYYO(IANG)=CYY                                                     ! D041
      CRTO(IANG)=CRT                                                     ! D041
C     WRITE(6,200)P2,CXX,CYY,CRT                                         ! D041
  200 FORMAT(1H0,5X,F12.6,8X,F12.6,8X,F12.6,8X,F12.6)
C     IF(P2.EQ.360.0) GO TO 1                                            ! D041
      IF (IANG.EQ.NANG) GO TO 1                                          ! D041
      GO TO 5
    1 RETURN                                                             ! D042
  998 ISTAT=IANG                                                         ! D042
      RETURN                                                             ! D042
      END
