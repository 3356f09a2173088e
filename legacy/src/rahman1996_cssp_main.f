C PROGRAM FOR OPTIMUM BALANCING OF THE GENERALIZED SLIDER
C CRANK MECHANISM (CSSP). KINEMATICS IS PERFORMED USING
C UICKER-DENAVIT-HARTENBERG METHOD.
C
C     [LINKREPRO] S. RAHMAN, PHD NJIT 1996, APPENDIX B: THE MAIN
C     PROGRAM ONLY (SEED LINES 1626-2943).  THE SUBROUTINES PRODUCTDUAL
C     ... INVERSE THAT FOLLOW IT IN THE LISTING ARE TRANSCRIBED
C     ELSEWHERE; QPROG AND UMACH ARE IMSL ROUTINES.  OCR DAMAGE IS
C     REPAIRED; LINES THE SCAN LOST ARE RECONSTRUCTED ONLY WHERE THE
C     PROGRAM CANNOT RUN WITHOUT THEM, EACH MARKED BY A [LINKREPRO]
C     COMMENT.  SEE THE TRANSCRIPTION NOTES FOR SEED LINES AND READINGS.
C
      SUBROUTINE CSSP(A1,A2,A4,AL4,S1,RPM,USESOL,SOLIN,TABLE,SOLOUT,    ! D051
     1 INERT,HOUT,DIAGO,ISTAT,FAILDG,QOUT,SOLAFT)                       ! D151
      INTEGER USESOL,ISTAT,IQP,IERINV                                   ! D051
      REAL SOLIN(9),SOLOUT(9),HOUT(9,9),DIAGO,FAILDG                    ! D051
      REAL SOLAFT(9)                                                    ! D151
      REAL*8 QOUT(5,37,2)                                               ! D053
      DOUBLE PRECISION TABLE(37,12),INERT(6,2)                          ! D051
      COMMON /INVERR/ IERINV                                            ! D052
C************Declaration of the variables*********************
C Joint variables
      REAL*8 THT1, THT2, ETA, ETA2, THT3, ETA3, ALP4, S4
C Derivatives of joint variables
      REAL*8 THT1D, THT2D, ETA2D, THT3D, ETA3D, S4D
C Double derivatives of joint variables
      REAL*8 THT2DD, ETA2DD, THT3DD, ETA3DD, S4DD
C Transformation matrices
      REAL*8 M1R(3,3),M1D(3,3),L2R(3,3),L2D(3,3),
     1 L3R(3,3),L3D(3,3),M4R(3,3),M4D(3,3)
C Differential operators of transformation matrices
C
C Q1=operator of M1, L2(wrt THT2) & L3(wrt THT3)
C Q2=operator of L2(wrt ETA2)
C Q3=operator of M4
C Q4=operator of L3(wrt ETA3)
      REAL*8 Q1R(3,3),Q1D(3,3),Q2R(3,3),Q2D(3,3),
     1 Q3R(3,3),Q3D(3,3),Q4R(3,3),Q4D(3,3)
C Derivatives, transpose, multiplications, etc of
C transformation matrices
      REAL*8 M1Q1R(3,3),M1Q1D(3,3),TM1R(3,3),TM1D(3,3),
     1 H2R(3,3),H2D(3,3),M1Q2R(3,3),M1Q2D(3,3),H2DR(3,3),
     1 H2DD(3,3),M1L2R(3,3),M1L2D(3,3),TM1L2R(3,3),
     1 TM1L2D(3,3),H6R(3,3),H6D(3,3),H3R(3,3),H3D(3,3),
     1 H7R(3,3),H7D(3,3),H3DR(3,3),H3DD(3,3),H5R(3,3),
     1 H5D(3,3),H5Q3R(3,3),H5Q3D(3,3),TH5R(3,3),TH5D(3,3),
     1 H4DDR(3,3),H4DDD(3,3),BR(3,3),BD(3,3),A(6,5),V(6),
     1 AT(5,6), ATA(5,5), IATA(5,5), DELTA(5), IA(5,6),
     1 L3M4R(3,3),L3M4D(3,3),TL3M4R(3,3),TL3M4D(3,3),
     1 TL3R(3,3),TM4R(3,3),L3RD(3,3),L3RDD(3,3),
     1 TM4L3R(3,3),TM4L3RD(3,3),TM4L3RDD(3,3)
C L3RD & L3RDD are the diff and double diff of TL3R
C Joint angles in degrees
      REAL*8 TH1, TH2, TH3, ET2, ET3, AL4
C Velocity components
      REAL*8 V2XP, V2XD, V2YP, V2YD, V2ZP, V2ZD
C Velocity and acceleration matrices
      REAL*8 VM(6,5),VMT(5,6),VMTVM(5,5),IVMTVM(5,5),
     1 IVM(5,6),VV(6),AV(6),DOT(5),DDOT(5)
C Mass properties (Radii of gyration, C.G.'s, masses & MOI)
C of the moving links
      REAL*8 K1X,K1Y,K1Z,K2X,K2Y,K2Z,K3X,K3Y,K3Z,
     1 K1XCG,K1YCG,K1ZCG,K2XCG,K2YCG,K2ZCG,
     1 G1,G2,G3,M1,M2,M3,I1X,I1Y,I1Z,I2X,I2Y,I2Z,
     1 I3X,I3Y,I3Z,NUI1X,NUI1Y,NUI1Z,NUI2X,NUI2Y,NUI2Z
C Momentum components and their derivatives
      REAL*8 H2XP,H2XD,H2YP,H2YD,H2ZP,H2ZD,
     1 H2DXP,H2DXD,H2DYP,H2DYD,H2DZP,H2DZD
C Inertia force and torque components
      REAL*8 R1P(3),R2P(3),R3P(3),R1D(3),R2D(3),R3D(3),
     1 M1R1P(3),M1R1D1(3),M1R1D2(3),M1R1D(3),
     1 M1L2R2P(3),M1L2R2D1(3),M1L2R2D2(3),M1L2R2D(3),
     1 TM4R3P(3),NUR1XP,NUR2XP,NUR1YP,NUR2YP,NUR1ZP,NUR2ZP,
     1 NUR1XD,NUR2XD,NUR1YD,NUR2YD,NUR1ZD,NUR2ZD
C Reaction force and torque components
      REAL*8 T1I,T1J,T1K,F1I,F1J,F1K,F2I,F2J,F2K,
     1 F2K1,F2K2,F3I,F3J,F3K,T4I,T4J,T4K,F4I,F4J,F4K
C Location of point masses and their derivatives
      REAL*8 D(3), DD(3), DDD(3), LL(3), LL1(3), LL2(3),
     1 L11DD(3),L12DD(3),L13DD(3),L14(3),L14D(3),L14DD(3),
     1 L111(3), L11D1(3), temp,
     1 L11DD1(3),L121(3),L12D1(3),L12DD1(3),L131(3),
     1 L13D1(3),L13DD1(3),L112(3),L11D2(3),
     1 L11DD2(3),L122(3),L12D2(3),L12DD2(3),L132(3),
     1 L13D2(3),L13DD2(3),L21DD(3),
     1 L22DD(3),L23DD(3),L24(3),L24D(3),L24DD(3),
     1 L211(3),L21D1(3),L21DD1(3),L221(3),L22D1(3),
     1 L22DD1(3),L231(3),L23D1(3),L23DD1(3),
     1 L212(3),L21D2(3),L21DD2(3),L222(3),L22D2(3),
     1 L22DD2(3),L232(3),L23D2(3),L23DD2(3)
      REAL*8 X10, Y10, Z10, X1, Y1, Z1, L1(3,3),
     1 X20, Y20, Z20, X2, Y2, Z2, L2(3,3)
      REAL*8 M1RD(3,3),M1RDD(3,3)
      REAL*8 PI,DEGRAD
      real*8 m11,m12,m13,m14,m21,m22,m23,m24,m(9)
C Variables required for optimization
      real*8 px(9),fx(9),fxsq(9,9),py(9),fy(9),fysq(9,9),
     1 pz(9),fz(9),fzsq(9,9),qx(9),tx(9),txsq(9,9),
     1 qy(9),ty(9),tysq(9,9),qz(9),tz(9),tzsq(9,9),
     1 f1x(9),f1xsq(9,9),f1y(9),f1ysq(9,9),
     1 f1z(9),f1zsq(9,9),t1x(9),t1xsq(9,9),
     1 t1y(9),t1ysq(9,9),t1z(9),t1zsq(9,9),
     1 f2x(9),f2xsq(9,9),f2y(9),f2ysq(9,9),
     1 f2z(9),f2zsq(9,9),f3x(9),f3xsq(9,9),
     1 f3y(9),f3ysq(9,9),f3z(9),f3zsq(9,9),
     1 f4x(9),f4xsq(9,9),f4y(9),f4ysq(9,9),
     1 t4x(9),t4xsq(9,9),t4y(9),t4ysq(9,9),
     1 t4z(9),t4zsq(9,9),f4z(9),f4zsq(9,9),
     1 fsq(9,9),tsq(9,9),rsq(9,9),msq(9,9),t0sq(9,9),
     1 F(9,9),OF(9,9),C1,C2,C3,OBJFUN,NUOBJFUN,
     1 mfx,nufx,mfy,nufy,mfz,nufz,mtx,nutx,mty,nuty,
     1 mtz,nutz,mf1x,nuf1x,mf1y,nuf1y,mf1z,nuf1z,
     1 mt1x,nut1x,mt1y,nut1y,mt1z,nut1z,mf2x,nuf2x,
     1 mf2y,nuf2y,mf2z,nuf2z,mf3x,nuf3x,mf3y,nuf3y,
     1 mf3z,nuf3z,mf4x,nuf4x,mf4y,nuf4y,mt4x,nut4x,
     1 mt4y,nut4y,mt4z,nut4z,shf,nushf,sht,nusht,
     1 brf,nubrf,brt,nubrt,int,nuint,DOBJFUN,dshf,
     1 dsht,dbrf,dbrt,dint
      integer lda,ldh,ncon,neq,nvar
      parameter (ncon=11,neq=3,nvar=9,lda=ncon,ldh=nvar)
      integer iact(nvar),k,nact,nout
      real aa(lda,nvar),alamda(nvar),b(ncon),diag,gg(nvar),
     1 h(ldh,ldh),sol(nvar)
      external qprog,umach
C     [LINKREPRO] ONLY TWO LINES OF THE DATA STATEMENT FOR AA SURVIVE
C     IN THE SCAN (SEED LINES 1674-1675; THEY ARE COLUMNS 7 AND 8
C     BELOW, THE SECOND WITH ONE 0.0 DROPPED).  THE REST IS
C     RECONSTRUCTED FROM B (ROWS: X1+X2+X3, X5+X6+X7, X9 = B(1..3);
C     X1..X4, X5..X8 >= B(4..11)), EQ. (4.5), SECTION 5.2.
      data aa/1.0,0.0,0.0,1.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,
     1 1.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,0.0,0.0,0.0,
     1 1.0,0.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,0.0,0.0,
     1 0.0,0.0,0.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,0.0,
     1 0.0,1.0,0.0,0.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,
     1 0.0,1.0,0.0,0.0,0.0,0.0,0.0,0.0,1.0,0.0,0.0,
     1 0.0,1.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,1.0,0.0,
     1 0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,1.0,
     1 0.0,0.0,1.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0/
      data b/0.003688,0.01475,0.01553,4*0.001168,4*0.00467/
      data gg/9*0.0/
C Weight factors and bearing length
      PARAMETER (W1=1,W2=1,W3=1,W4=1,W5=1,BL=0.4)
C LINK PARAMETERS ARE AS FOLLOWS
C     PARAMETER (A1=2.0,A2=8.0,A4=1.0,AL4=250.0,S1=0.4)                 ! D051
C     PARAMETER (G=386.4,RPM=3000.0,THT1DD=0.0,                         ! D051
      PARAMETER (G=386.4,THT1DD=0.0,                                    ! D051
     1 S1D=0.0,S1DD=0.0)
C     OPEN (6,FILE='dint.dat',STATUS='new')                             ! D053
      ISTAT=0                                                           ! D052
      IERINV=0                                                          ! D052
      FAILDG=0.0                                                        ! D052
      ETA2=0.0                                                          ! D054
      ETA3=0.0                                                          ! D054
      fy(9)=0.0                                                         ! D054
      fz(9)=0.0                                                         ! D054
      f3x(8)=0.0                                                        ! D054
      PI=4.0*ATAN(1.0)
      DEGRAD=PI/180.0
C Mass properties of the original links
      G1=-1.0
      G2=-4.0
      G3=0.0
      M1=1.9/G
      M2=7.6/G
      M3=6.0/G
C Radii of gyration about C.G. & about distal coordinate frame
      K1XCG=0.2041241D0                                                 ! D180
      K1YCG=0.595119D0                                                  ! D180
      K1ZCG=0.595119D0                                                  ! D180
      K1X=0.2041241D0                                                   ! D180
      K1Y=1.1636867D0                                                   ! D180
      K1Z=1.1636867D0                                                   ! D180
      K2XCG=0.2041241D0                                                 ! D180
      K2YCG=2.3139072D0                                                 ! D180
      K2ZCG=2.3139072D0                                                 ! D180
      K2X=0.2041241D0                                                   ! D180
      K2Y=4.6210569D0                                                   ! D180
      K2Z=4.6210569D0                                                   ! D180
      K3X=0.5204165D0                                                   ! D180
      K3Y=0.5204165D0                                                   ! D180
      K3Z=0.7071067D0                                                   ! D180
C Mass moment of inertia about C.G.
      I1X=M1*K1XCG**2
      I1Y=M1*K1YCG**2
      I1Z=M1*K1ZCG**2
      I2X=M2*K2XCG**2
      I2Y=M2*K2YCG**2
      I2Z=M2*K2ZCG**2
      I3X=M3*K3X**2
      I3Y=M3*K3Y**2
      I3Z=M3*K3Z**2
      X10=G1
      X20=G2
      m11=M1/4.0
      m12=m11
      m13=m11
      m14=M1-(m11+m12+m13)
      m21=M2/4.0
      m22=m21
      m23=m21
      m24=M2-(m21+m22+m23)
      m(1)=m11
      m(2)=m12
      m(3)=m13
      m(4)=m14
      m(5)=m21
      m(6)=m22
      m(7)=m23
      m(8)=m24
      m(9)=M3
C Direction cosines between distal & principal coordinate frames
      L1(1,1)=1.0
      L1(2,2)=1.0
      L1(3,3)=1.0
      L2(1,1)=1.0
      L2(2,2)=1.0
      L2(3,3)=1.0
C Location of point masses
      X1=((I1Y+I1Z-I1X)/(2.0*m11))**0.5
      Y1=((I1X+I1Z-I1Y)/(2.0*m12))**0.5
      Z1=((I1X+I1Y-I1Z)/(2.0*m13))**0.5
      X2=((I2Y+I2Z-I2X)/(2.0*m21))**0.5
      Y2=((I2X+I2Z-I2Y)/(2.0*m22))**0.5
      Z2=((I2X+I2Y-I2Z)/(2.0*m23))**0.5
C Initialization of the objective function OF(9,9)
      DO 100 I2=1,9
      DO 110 J2=1,9
      OF(I2,J2)=0
  110 CONTINUE
  100 CONTINUE
      do 41 I3=1,2
C INITIAL ESTIMATE FOR DISPLACEMENTS
      S4=(A2**2-(A1+A4)**2)**0.5
      temp=S4/(A4+A1)
      THT2=PI-ATAN(temp)
C     THT2=PI-ATAN2(S4,(A4+A1))
      THT3=2*PI-THT2
      DO 400 J=1,37
      TH1=J*10.0-10.0
      THT1=TH1*DEGRAD
      ALP4=AL4*DEGRAD
      THT1D=6.0*RPM*DEGRAD
C STEP 1
      I=1
   10 IF (I.LE.150) THEN
C SPECIFICATION OF M1,L2,L3,M4 MATRICES RESPECTIVELY
      M1R(1,1)=COS(THT1)
      M1R(1,2)=-SIN(THT1)
      M1R(1,3)=0.0
      M1R(2,1)=SIN(THT1)
      M1R(2,2)=COS(THT1)
      M1R(2,3)=0.0
      M1R(3,1)=0.0
      M1R(3,2)=0.0
      M1R(3,3)=1.0
          M1D(1,1)=-S1*SIN(THT1)
          M1D(1,2)=-S1*COS(THT1)
          M1D(1,3)=A1*SIN(THT1)
          M1D(2,1)=S1*COS(THT1)
          M1D(2,2)=-S1*SIN(THT1)
          M1D(2,3)=-A1*COS(THT1)
          M1D(3,1)=0.0
          M1D(3,2)=A1
          M1D(3,3)=0.0
C
      L2R(1,1)=COS(THT2)*COS(ETA2)
      L2R(1,2)=-SIN(THT2)
      L2R(1,3)=COS(THT2)*SIN(ETA2)
      L2R(2,1)=SIN(THT2)*COS(ETA2)
      L2R(2,2)=COS(THT2)
      L2R(2,3)=SIN(THT2)*SIN(ETA2)
      L2R(3,1)=-SIN(ETA2)
C     [LINKREPRO] L2R(3,2) AND L2R(3,3) ARE LOST IN THE SCAN (SEED LINE
C     1765); RECONSTRUCTED FROM EQ. (2.6).
      L2R(3,2)=0.0
      L2R(3,3)=COS(ETA2)
          L2D(1,1)=0.0
          L2D(1,2)=A2*COS(THT2)*SIN(ETA2)
          L2D(1,3)=A2*SIN(THT2)
          L2D(2,1)=0.0
          L2D(2,2)=A2*SIN(THT2)*SIN(ETA2)
          L2D(2,3)=-A2*COS(THT2)
          L2D(3,1)=0.0
          L2D(3,2)=A2*COS(ETA2)
          L2D(3,3)=0.0
C
C
      L3R(1,1)=COS(THT3)*COS(ETA3)
      L3R(1,2)=COS(THT3)*SIN(ETA3)
      L3R(1,3)=SIN(THT3)
      L3R(2,1)=SIN(THT3)*COS(ETA3)
      L3R(2,2)=SIN(THT3)*SIN(ETA3)
      L3R(2,3)=-COS(THT3)
      L3R(3,1)=-SIN(ETA3)
      L3R(3,2)=COS(ETA3)
      L3R(3,3)=0.0
          L3D(1,1)=0.0
          L3D(1,2)=0.0
          L3D(1,3)=0.0
          L3D(2,1)=0.0
          L3D(2,2)=0.0
          L3D(2,3)=0.0
          L3D(3,1)=0.0
          L3D(3,2)=0.0
          L3D(3,3)=0.0
      M4R(1,1)=1.0
      M4R(1,2)=0.0
      M4R(1,3)=0.0
      M4R(2,1)=0.0
      M4R(2,2)=COS(ALP4)
      M4R(2,3)=-SIN(ALP4)
      M4R(3,1)=0.0
      M4R(3,2)=SIN(ALP4)
      M4R(3,3)=COS(ALP4)
          M4D(1,1)=0.0
          M4D(1,2)=-S4*COS(ALP4)
          M4D(1,3)=S4*SIN(ALP4)
          M4D(2,1)=S4
          M4D(2,2)=-A4*SIN(ALP4)
          M4D(2,3)=-A4*COS(ALP4)
          M4D(3,1)=0.0
          M4D(3,2)=A4*COS(ALP4)
          M4D(3,3)=-A4*SIN(ALP4)
C
C SPECIFICATION OF PARTIAL DERIVATIVE OPERATORS
      Q1R(1,2)=-1.0
      Q1R(2,1)=1.0
      Q2R(1,3)=COS(THT2)
      Q2R(2,3)=SIN(THT2)
      Q2R(3,1)=-COS(THT2)
      Q2R(3,2)=-SIN(THT2)
      Q3D(1,2)=-1.0
      Q3D(2,1)=1.0
      Q4R(1,3)=COS(THT3)
      Q4R(2,3)=SIN(THT3)
      Q4R(3,1)=-COS(THT3)
      Q4R(3,2)=-SIN(THT3)
C
      CALL PRODUCTDUAL (M1R,M1D,Q1R,Q1D,M1Q1R,M1Q1D)
        CALL TRANSPOSE (M1R,M1D,TM1R,TM1D)
      CALL PRODUCTDUAL (M1Q1R,M1Q1D,TM1R,TM1D,H2R,H2D)
      CALL PRODUCTDUAL (M1R,M1D,Q2R,Q2D,M1Q2R,M1Q2D)
      CALL PRODUCTDUAL (M1Q2R,M1Q2D,TM1R,TM1D,H2DR,H2DD)
      CALL PRODUCTDUAL (M1R,M1D,L2R,L2D,M1L2R,M1L2D)
        CALL TRANSPOSE (M1L2R,M1L2D,TM1L2R,TM1L2D)
      CALL PRODUCTDUAL (M1L2R,M1L2D,Q1R,Q1D,H6R,H6D)
      CALL PRODUCTDUAL (H6R,H6D,TM1L2R,TM1L2D,H3R,H3D)
      CALL PRODUCTDUAL (M1L2R,M1L2D,Q4R,Q4D,H7R,H7D)
      CALL PRODUCTDUAL (H7R,H7D,TM1L2R,TM1L2D,H3DR,H3DD)
      CALL PRODUCTDUAL (M1L2R,M1L2D,L3R,L3D,H5R,H5D)
      CALL PRODUCTDUAL (H5R,H5D,Q3R,Q3D,H5Q3R,H5Q3D)
        CALL TRANSPOSE (H5R,H5D,TH5R,TH5D)
      CALL PRODUCTDUAL (H5Q3R,H5Q3D,TH5R,TH5D,H4DDR,H4DDD)
      CALL PRODUCTDUAL (H5R,H5D,M4R,M4D,BR,BD)
      CALL PRODUCTDUAL (L3R,L3D,M4R,M4D,L3M4R,L3M4D)
        CALL TRANSPOSE (L3M4R,L3M4D,TL3M4R,TL3M4D)
C SPECIFICATION OF A & V MATRICES
      A(1,1)=H2R(1,2)
      A(1,2)=H2DR(1,2)
      A(1,3)=H3R(1,2)
      A(1,4)=H3DR(1,2)
      A(1,5)=H4DDR(1,2)
      A(2,1)=H2R(1,3)
      A(2,2)=H2DR(1,3)
      A(2,3)=H3R(1,3)
      A(2,4)=H3DR(1,3)
      A(2,5)=H4DDR(1,3)
      A(3,1)=H2R(2,3)
      A(3,2)=H2DR(2,3)
      A(3,3)=H3R(2,3)
      A(3,4)=H3DR(2,3)
      A(3,5)=H4DDR(2,3)
      A(4,1)=H2D(1,2)
      A(4,2)=H2DD(1,2)
      A(4,3)=H3D(1,2)
      A(4,4)=H3DD(1,2)
      A(4,5)=H4DDD(1,2)
      A(5,1)=H2D(1,3)
      A(5,2)=H2DD(1,3)
      A(5,3)=H3D(1,3)
      A(5,4)=H3DD(1,3)
      A(5,5)=H4DDD(1,3)
      A(6,1)=H2D(2,3)
      A(6,2)=H2DD(2,3)
      A(6,3)=H3D(2,3)
      A(6,4)=H3DD(2,3)
      A(6,5)=H4DDD(2,3)
C
      V(1)=BR(2,1)+BR(1,1)+BR(2,2)-2.0
      V(2)=BR(3,1)+BR(1,1)+BR(3,3)-2.0
      V(3)=BR(3,2)+BR(2,2)+BR(3,3)-2.0
      V(4)=BD(2,1)
      V(5)=BD(3,1)
      V(6)=BD(3,2)
C Determination of joint variables
      CALL TRANS (A,AT,6,5)
      CALL MULTI (AT,A,ATA,5,5,6)
      CALL INVERSE (ATA,IATA)
      IF (IERINV.NE.0) THEN                                             ! D052
      ISTAT=2                                                           ! D052
      FAILDG=TH1                                                        ! D052
      RETURN                                                            ! D052
      ENDIF                                                             ! D052
      CALL MULTI (IATA,AT,IA,5,6,5)
      CALL MULMAVEC (IA,V,DELTA,5,6)
C
      IF (ABS(DELTA(1)) .LE. 0.0000001 .AND.
     1    ABS(DELTA(2)) .LE. 0.0000001 .AND.
     1    ABS(DELTA(3)) .LE. 0.0000001 .AND.
     1    ABS(DELTA(3)) .LE. 0.0000001 .AND.
     1    ABS(DELTA(4)) .LE. 0.0000001 .AND.
     1    ABS(DELTA(5)) .LE. 0.0000001) THEN
      TH2=THT2/DEGRAD
      TH3=THT3/DEGRAD
      ET2=ETA2/DEGRAD
      ET3=ETA3/DEGRAD
      QOUT(1,J,I3)=THT2                                                 ! D053
      QOUT(2,J,I3)=ETA2                                                 ! D053
      QOUT(3,J,I3)=THT3                                                 ! D053
      QOUT(4,J,I3)=ETA3                                                 ! D053
      QOUT(5,J,I3)=S4                                                   ! D053
C Derivative of joint variables
      VM(1,1)=-SIN(ETA2)
      VM(1,3)=SIN(THT2)*COS(ETA2)
      VM(2,5)=SIN(THT3)
      VM(3,3)=COS(THT2)
      VM(3,4)=1.0
      VM(4,1)=A2*COS(ETA2)
      VM(4,3)=A2*SIN(THT2)*SIN(ETA2)
      VM(4,5)=-COS(THT3)
      VM(5,1)=COS(ETA2)
      VM(5,1)=COS(ETA2)
      VM(5,2)=1.0
      VM(5,3)=SIN(THT2)*SIN(ETA2)
      VM(6,3)=-A2*COS(THT2)
C
      VV(1)=THT1D*SIN(ETA2)
      VV(2)=S1D*SIN(ETA2)-A1*THT1D*SIN(THT2)*COS(ETA2)
      VV(4)=-THT1D*(A1*COS(THT2)+A2*COS(ETA2))
      VV(5)=-THT1D*COS(ETA2)
      VV(6)=-THT1D*A1*SIN(THT2)*SIN(ETA2)-S1D*COS(ETA2)
C
      CALL TRANS (VM,VMT,6,5)
      CALL MULTI (VMT,VM,VMTVM,5,5,6)
      CALL INVERSE (VMTVM,IVMTVM)
      IF (IERINV.NE.0) THEN                                             ! D052
      ISTAT=2                                                           ! D052
      FAILDG=TH1                                                        ! D052
      RETURN                                                            ! D052
      ENDIF                                                             ! D052
      CALL MULTI (IVMTVM,VMT,IVM,5,6,5)
      CALL MULMAVEC (IVM,VV,DOT,5,6)
C
      THT2D=DOT(1)
      THT3D=DOT(2)
      ETA2D=DOT(3)
      ETA3D=DOT(4)
      S4D=DOT(5)
C Double derivative of joint variables
      AV(1)=THT1DD*SIN(ETA2)+ETA2D*(THT1D+THT2D)*COS(ETA2)
     1 -ETA2D*(THT2D*COS(THT2)*COS(ETA2)-ETA2D*
     1 SIN(THT2)*SIN(ETA2))
      AV(2)=A1*(THT1D*SIN(THT2)*SIN(ETA2)*ETA2D-THT1DD*
     1 SIN(THT2)*COS(ETA2)-THT1D*THT2D*COS(THT2)*COS(ETA2))
     1 +S1DD*SIN(ETA2)+S1D*ETA2D*COS(ETA2)-S4D*THT3D*COS(THT3)
      AV(3)=THT2D*ETA2D*SIN(THT2)
      AV(4)=A1*SIN(THT2)*THT1D*THT2D+A2*SIN(ETA2)*ETA2D*
     1 (THT1D+THT2D)-THT1DD*(A1*COS(THT2)+A2*COS(ETA2))
     1 -A2*ETA2D*(COS(THT2)*SIN(ETA2)*THT2D+SIN(THT2)*
     1 COS(ETA2)*ETA2D)-SIN(THT3)*THT3D*S4D
      AV(5)=THT1D*ETA2D*SIN(ETA2)-THT1DD*COS(ETA2)+SIN(ETA2)*
     1 ETA2D*THT2D-ETA2D*(COS(THT2)*SIN(ETA2)*THT2D+
     1 SIN(THT2)*COS(ETA2)*ETA2D)
      AV(6)=S1D*SIN(ETA2)*ETA2D-A1*THT1DD*SIN(THT2)*SIN(ETA2)
     1 -A1*THT1D*THT2D*COS(THT2)*SIN(ETA2)-S1DD*COS(ETA2)
     1 -A1*SIN(THT2)*COS(ETA2)*THT1D*ETA2D
     1 -A2*THT2D*ETA2D*SIN(THT2)
      CALL MULMAVEC (IVM,AV,DDOT,5,6)
      THT2DD=DDOT(1)
      THT3DD=DDOT(2)
      ETA2DD=DDOT(3)
      ETA3DD=DDOT(4)
      S4DD=DDOT(5)
C Inertia forces and torques of original links
      V2XP=0.0
      V2XD=-S4D*SIN(THT3)
      V2YP=-ETA3D
      V2YD=S4D*COS(THT3)
      V2ZP=-THT3D
      V2ZD=0.0
      H2XP=-S4D*SIN(THT3)
      H2XD=0.0
      H2YP=-G2*THT3D+S4D*COS(THT3)
      H2YD=-(K2Y**2)*ETA3D
      H2ZP=ETA3D*G2
      H2ZD=-(K2Z**2)*THT3D+G2*S4D*COS(THT3)
C
      H2DXP=-S4DD*SIN(THT3)-S4D*THT3D*COS(THT3)
      H2DXD=0.0
      H2DYP=-G2*THT3DD-THT3D*S4D*SIN(THT3)+
     1S4DD*COS(THT3)
      H2DYD=-(K2Y**2)*ETA3DD
      H2DZP=G2*ETA3DD
      H2DZD=-(K2Z**2)*THT3DD+G2*(S4DD*COS(THT3)-SIN(THT3)*
     1THT3D*S4D)
C
      R1P(1)=-M1*(THT1D**2)*(A1+G1)
      R1D(1)=0.0
      R1P(2)=M1*THT1DD*(A1+G1)
      R1D(2)=-M1*G1*S1DD
      R1P(3)=M1*S1DD
      R1D(3)=M1*THT1DD*((K1Z**2)+G1*A1)
      CALL MULMAVEC (M1R,R1P,M1R1P,3,3)
      CALL MULMAVEC (M1R,R1D,M1R1D1,3,3)
      CALL MULMAVEC (M1D,R1P,M1R1D2,3,3)
      CALL ADDVEC (M1R1D1,M1R1D2,M1R1D)
C
      R2P(1)=M2*(H2DXP-V2ZP*H2YP+V2YP*H2ZP)
      R2D(1)=M2*(H2DXD-V2ZP*H2YD-V2ZD*H2YP+V2YP*H2ZD+V2YD*H2ZP)
      R2P(2)=M2*(H2DYP-V2XP*H2ZP+V2ZP*H2XP)
      R2D(2)=M2*(H2DYD-V2XP*H2ZD-V2XD*H2ZP+V2ZP*H2XD+V2ZD*H2XP)
      R2P(3)=M2*(H2DZP-V2YP*H2XP+V2XP*H2YP)
      R2D(3)=M2*(H2DZD-V2YP*H2XD-V2YD*H2XP+V2XP*H2YD+V2XD*H2YP)
C     CALL MULMAVEC (M1L2R,R2P,M1L2R2P,3,3)
C     CALL MULMAVEC (M1L2R,R2D,M1L2R2D1,3,3)
C     CALL MULMAVEC (M1L2D,R2P,M1L2R2D2,3,3)
C     CALL ADDVEC (M1L2R2D1,M1L2R2D2,M1L2R2D)
      CALL MULMAVEC (TL3M4R,R2P,M1L2R2P,3,3)
      CALL MULMAVEC (TL3M4R,R2D,M1L2R2D1,3,3)
      CALL MULMAVEC (TL3M4D,R2P,M1L2R2D2,3,3)
      CALL ADDVEC (M1L2R2D1,M1L2R2D2,M1L2R2D)
C
      R3P(1)=0.0
      R3D(1)=0.0
      R3P(2)=0.0
      R3D(2)=M3*G3*S4DD
      R3D(3)=-M3*S4DD
      R3D(3)=0.0
      CALL TRANS (L3R,TL3R,3,3)
      CALL TRANS (M4R,TM4R,3,3)
      CALL MULMAVEC (TM4R,R3P,TM4R3P,3,3)
      CALL MULTI (TM4R,TL3R,TM4L3R,3,3,3)
C Joint forces and torques of the original links
      F3J=-(R2P(2)+R2D(3)/A2)
      F3K=R2D(2)/A2-R2P(3)
      T4I=-R3D(1)
      T4J=-R3D(2)
      T4K=-R3D(3)
      F3I=(F3J*COS(THT3)-F4K-R3P(3))/SIN(THT3)
      F4J=-(COS(THT3)*SIN(ETA3)*F3I+SIN(THT3)*SIN(ETA3)*F3J+
     1 COS(ETA3)*F3K+R3P(2))
      F4I=-(COS(THT3)*COS(ETA3)*F3I+SIN(THT3)*COS(ETA3)*F3J-
     1 SIN(ETA3)*F3K+R3P(1))
      F2J=-(F3J+R2P(2))*COS(THT2)-R2D(2)*SIN(ETA2)*SIN(THT2)/A2
     1 -(F3I+R2P(1))*SIN(THT2)*COS(ETA2)
      F2I=(F3J+R2P(2))*SIN(THT2)-R2D(2)*SIN(ETA2)*COS(THT2)/A2
     1 -(F3I+R2P(1))*COS(THT2)*COS(ETA2)
      F2K1=-(F2I*COS(THT2)*SIN(ETA2)+F2J*SIN(THT2)*SIN(ETA2)+
     1 F3K+R2P(3))
      F2K2=(F2I*COS(THT2)*COS(ETA2)+F2J*SIN(THT2)*COS(ETA2)+
     1 F3I+R2P(1))
      temp=F2K2/F2K1
      ETA=ATAN(temp)
      ETA=ATAN2(F2K2,F2K1)
C
      if (ABS(COS(ETA)).GT. ABS(SIN(ETA))) then
      F2K=F2K1/COS(ETA)
      else
      F2K=F2K2/SIN(ETA)
      endif
      F1K=-(F2K+R1P(3))
      F1I=-(F2I+R1P(1))*COS(THT1)+(F2J+R1P(2))*SIN(THT1)
      F1J=-(F2I+R1P(1))*SIN(THT1)-(F2J+R1P(2))*COS(THT1)
      T1K=COS(THT1)*A1*F1J-SIN(THT1)*A1*F1I-R1D(3)
      T1J=S1*F1I-R1D(1)*SIN(THT1)-(A1*F1K+R1D(2))*COS(THT1)
      T1I=-S1*F1J-R1D(1)*COS(THT1)+(A1*F1K+R1D(2))*SIN(THT1)
C
C     USE OF POINT MASSES
C For Crank (link 1)
      D(1)=A1*COS(THT1)
      DD(1)=-A1*SIN(THT1)*THT1D
      DDD(1)=-A1*(COS(THT1)*THT1D**2+SIN(THT1)*THT1DD)
      D(2)=A1*SIN(THT1)
      DD(2)=A1*COS(THT1)*THT1D
      DDD(2)=A1*(COS(THT1)*THT1DD-SIN(THT1)*THT1D**2)
      D(3)=S1
      DD(3)=S1D
      DDD(3)=S1DD
C Derivative and double derivative of M1R
      M1RD(1,1)=-SIN(THT1)*THT1D
      M1RD(1,2)=-COS(THT1)*THT1D
      M1RD(2,1)=COS(THT1)*THT1D
      M1RD(2,2)=-SIN(THT1)*THT1D
      M1RDD(1,1)=-SIN(THT1)*THT1DD-COS(THT1)*(THT1D**2)
      M1RDD(1,2)=-COS(THT1)*THT1DD+SIN(THT1)*(THT1D**2)
      M1RDD(2,1)=COS(THT1)*THT1DD-SIN(THT1)*(THT1D**2)
      M1RDD(2,2)=-SIN(THT1)*THT1DD-COS(THT1)*(THT1D**2)
C Point mass m11
      LL1(1)=X10+X1*L1(1,1)
      LL1(2)=Y10+X1*L1(1,2)
      LL1(3)=Z10+X1*L1(1,3)
      LL2(1)=X10-X1*L1(1,1)
      LL2(2)=Y10-X1*L1(1,2)
      LL2(3)=Z10-X1*L1(1,3)
      CALL KINEMATIC (M1R,M1RD,M1RDD,D,DD,DDD,LL1,
     1 L111,L11D1,L11DD1)
      CALL KINEMATIC (M1R,M1RD,M1RDD,D,DD,DDD,LL2,
     1 L112,L11D2,L11DD2)
      CALL ADDVEC (L11DD1,L11DD2,L11DD)
C Point mass m12
      LL1(1)=X10+Y1*L1(2,1)
      LL1(2)=Y10+Y1*L1(2,2)
      LL1(3)=Z10+Y1*L1(2,3)
      LL2(1)=X10-Y1*L1(2,1)
      LL2(2)=Y10-Y1*L1(2,2)
      LL2(3)=Z10-Y1*L1(2,3)
      CALL KINEMATIC (M1R,M1RD,M1RDD,D,DD,DDD,LL1,
     1 L121,L12D1,L12DD1)
      CALL KINEMATIC (M1R,M1RD,M1RDD,D,DD,DDD,LL2,
     1 L122,L12D2,L12DD2)
      CALL ADDVEC (L12DD1,L12DD2,L12DD)
C Point mass m13
      LL1(1)=X10+Z1*L1(3,1)
      LL1(2)=Y10+Z1*L1(3,2)
      LL1(3)=Z10+Z1*L1(3,3)
      LL2(1)=X10-Z1*L1(3,1)
      LL2(2)=Y10-Z1*L1(3,2)
      LL2(3)=Z10-Z1*L1(3,3)
      CALL KINEMATIC (M1R,M1RD,M1RDD,D,DD,DDD,LL1,
     1 L131,L13D1,L13DD1)
      CALL KINEMATIC (M1R,M1RD,M1RDD,D,DD,DDD,LL2,
     1 L132,L13D2,L13DD2)
      CALL ADDVEC (L13DD1,L13DD2,L13DD)
C Point mass m14
      LL(1)=X10
      LL(2)=Y10
      LL(3)=Z10
      CALL KINEMATIC (M1R,M1RD,M1RDD,D,DD,DDD,LL,
     1 L14,L14D,L14DD)
C New inertia forces and torques of crank using point masses
      NUR1XP=(-m11*L11DD(1)-m12*L12DD(1)-m13*L13DD(1))/2
     1     -m14*L14DD(1)
      NUR1YP=(-m11*L11DD(2)-m12*L12DD(2)-m13*L13DD(2))/2
     1     -m14*L14DD(2)
      NUR1ZP=(-m11*L11DD(3)-m12*L12DD(3)-m13*L13DD(3))/2
     1     -m14*L14DD(3)
      NUR1XD=-m11*(L111(2)*L11DD1(3)-L111(3)*L11DD1(2))/2
     1     -m11*(L112(2)*L11DD2(3)-L112(3)*L11DD2(2))/2
     1     -m12*(L121(2)*L12DD1(3)-L121(3)*L12DD1(2))/2
     1     -m12*(L122(2)*L12DD2(3)-L122(3)*L12DD2(2))/2
     1     -m13*(L131(2)*L13DD1(3)-L131(3)*L13DD1(2))/2
     1     -m13*(L132(2)*L13DD2(3)-L132(3)*L13DD2(2))/2
     1     -m14*(L14(2)*L14DD(3)-L14(3)*L14DD(2))
      NUR1YD=-m11*(L111(3)*L11DD1(1)-L111(1)*L11DD1(3))/2
     1     -m11*(L112(3)*L11DD2(1)-L112(1)*L11DD2(3))/2
     1     -m12*(L121(3)*L12DD1(1)-L121(1)*L12DD1(3))/2
     1     -m12*(L122(3)*L12DD2(1)-L122(1)*L12DD2(3))/2
     1     -m13*(L131(3)*L13DD1(1)-L131(1)*L13DD1(3))/2
     1     -m13*(L132(3)*L13DD2(1)-L132(1)*L13DD2(3))/2
     1     -m14*(L14(3)*L14DD(1)-L14(1)*L14DD(3))
      NUR1ZD=-m11*(L111(1)*L11DD1(2)-L111(2)*L11DD1(1))/2
     1     -m11*(L112(1)*L11DD2(2)-L112(2)*L11DD2(1))/2
     1     -m12*(L121(1)*L12DD1(2)-L121(2)*L12DD1(1))/2
     1     -m12*(L122(1)*L12DD2(2)-L122(2)*L12DD2(1))/2
     1     -m13*(L131(1)*L13DD1(2)-L131(2)*L13DD1(1))/2
     1     -m13*(L132(1)*L13DD2(2)-L132(2)*L13DD2(1))/2
     1     -m14*(L14(1)*L14DD(2)-L14(2)*L14DD(1))
C For Connecting rod (link 2)
      D(1)=-A4
      D(2)=-S4*SIN(ALP4)
      D(3)=-S4*COS(ALP4)
      DD(1)=0.0
      DD(2)=-S4D*SIN(ALP4)
      DD(3)=-S4D*COS(ALP4)
      DDD(1)=0.0
      DDD(2)=-S4DD*SIN(ALP4)
      DDD(3)=-S4DD*COS(ALP4)
C     [LINKREPRO] THE BOTTOM OF A PAGE IS LOST IN THE SCAN (SEED LINES
C     2191/2194): THE FIRST THREE ELEMENTS OF L3RD ARE RECONSTRUCTED AS
C     THE TIME DERIVATIVE OF TL3R, THE TRANSPOSE OF EQ. (2.7); ONLY
C     THE LAST TERM OF L3RD(1,2) SURVIVES (SEED LINE 2194).  THE
C     COMMENT LINE IS MODELLED ON THE ONE BEFORE L3RDD.
C******Derivative of (TM4R)(TL3R)=TM4L3RD********
      L3RD(1,1)=-SIN(THT3)*COS(ETA3)*THT3D
     1      -COS(THT3)*SIN(ETA3)*ETA3D
      L3RD(1,3)=-COS(ETA3)*ETA3D
      L3RD(1,2)=COS(THT3)*COS(ETA3)*THT3D
     1      -SIN(THT3)*SIN(ETA3)*ETA3D
      L3RD(2,1)=COS(THT3)*COS(ETA3)*ETA3D
     1      -SIN(THT3)*SIN(ETA3)*THT3D
      L3RD(2,3)=-SIN(ETA3)*ETA3D
      L3RD(2,2)=COS(THT3)*SIN(ETA3)*THT3D
     1      +SIN(THT3)*COS(ETA3)*ETA3D
      L3RD(3,1)=COS(THT3)*THT3D
      L3RD(3,3)=0.0
      L3RD(3,2)=SIN(THT3)*THT3D
          CALL MULTI (TM4R,L3RD,TM4L3RD,3,3,3)
C******Double derivative of (TM4R)(TL3R)=TM4L3RDD********
      L3RDD(1,1)=2*SIN(THT3)*SIN(ETA3)*THT3D*ETA3D
     1      -COS(THT3)*COS(EAT3)*((THT3D**2)+(ETA3D**2))
     1      -SIN(THT3)*COS(ETA3)*THT3DD
     1      -COS(THT3)*SIN(ETA3)*ETA3DD
      L3RDD(1,3)=SIN(ETA3)*(ETA3D**2)-COS(ETA3)*ETA3DD
      L3RDD(1,2)=-2*SIN(ETA3)*COS(THT3)*THT3D*ETA3D
     1      -SIN(THT3)*COS(EAT3)*((THT3D**2)+(ETA3D**2))
     1      -SIN(THT3)*SIN(ETA3)*ETA3DD
     1      +COS(THT3)*COS(ETA3)*THT3DD
      L3RDD(2,1)=-2*SIN(THT3)*COS(ETA3)*THT3D*ETA3D
     1      -COS(THT3)*SIN(EAT3)*((THT3D**2)+(ETA3D**2))
     1      +COS(THT3)*COS(ETA3)*ETA3DD
     1      -SIN(THT3)*SIN(ETA3)*THT3DD
      L3RDD(2,3)=-COS(ETA3)*(ETA3D**2)-SIN(ETA3)*ETA3DD
      L3RDD(2,2)=2*COS(THT3)*COS(ETA3)*THT3D*ETA3D
     1      -SIN(THT3)*SIN(EAT3)*((THT3D**2)+(ETA3D**2))
     1      +COS(THT3)*SIN(ETA3)*THT3DD
     1      +SIN(THT3)*COS(ETA3)*ETA3DD
      L3RDD(3,1)=-SIN(THT3)*(THT3D**2)+COS(THT3)*THT3DD
      L3RDD(3,3)=0.0
      L3RDD(3,2)=COS(THT3)*(THT3D**2)+SIN(THT3)*THT3DD
          CALL MULTI (TM4R,L3RDD,TM4L3RDD,3,3,3)
C     [LINKREPRO] THE START OF THE POINT MASS M21 BLOCK IS LOST IN THE
C     SCAN (SEED LINES 2242/2244: ONLY THE SECOND CORRLS CALL AND THE
C     ADDVEC SURVIVE).  RECONSTRUCTED ON THE PATTERN OF M22 AND M23
C     AND OF M11, EQS. (2.71A,B).
C Point mass m21
      LL1(1)=X20+X2*L2(1,1)
      LL1(2)=Y20+X2*L2(1,2)
      LL1(3)=Z20+X2*L2(1,3)
      LL2(1)=X20-X2*L2(1,1)
      LL2(2)=Y20-X2*L2(1,2)
      LL2(3)=Z20-X2*L2(1,3)
      CALL CORRLS (TM4L3R,TM4L3RD,TM4L3RDD,D,DD,DDD,LL1,
     1 L211,L21D1,L21DD1)
      CALL CORRLS (TM4L3R,TM4L3RD,TM4L3RDD,D,DD,DDD,LL2,
     1 L212,L21D2,L21DD2)
      CALL ADDVEC (L21DD1,L21DD2,L21DD)
C Point mass m22
      LL1(1)=X20+Y2*L2(2,1)
      LL1(2)=Y20+Y2*L2(2,2)
      LL1(3)=Z20+Y2*L2(2,3)
      LL2(1)=X20-Y2*L2(2,1)
      LL2(2)=Y20-Y2*L2(2,2)
      LL2(3)=Z20-Y2*L2(2,3)
      CALL CORRLS (TM4L3R,TM4L3RD,TM4L3RDD,D,DD,DDD,LL1,
     1 L221,L22D1,L22DD1)
      CALL CORRLS (TM4L3R,TM4L3RD,TM4L3RDD,D,DD,DDD,LL2,
     1 L222,L22D2,L22DD2)
      CALL ADDVEC (L22DD1,L22DD2,L22DD)
C Point mass m23
      LL1(1)=X20+Z2*L2(3,1)
      LL1(2)=Y20+Z2*L2(3,2)
      LL1(3)=Z20+Z2*L2(3,3)
      LL2(1)=X20-Z2*L2(3,1)
      LL2(2)=Y20-Z2*L2(3,2)
      LL2(3)=Z20-Z2*L2(3,3)
      CALL CORRLS (TM4L3R,TM4L3RD,TM4L3RDD,D,DD,DDD,LL1,
     1 L231,L23D1,L23DD1)
      CALL CORRLS (TM4L3R,TM4L3RD,TM4L3RDD,D,DD,DDD,LL2,
     1 L232,L23D2,L23DD2)
      CALL ADDVEC (L23DD1,L23DD2,L23DD)
C Point mass m24
      LL(1)=X20
      LL(2)=Y20
      LL(3)=Z20
      CALL CORRLS (TM4L3R,TM4L3RD,TM4L3RDD,D,DD,DDD,LL,
     1 L24,L24D,L24DD)
C New inertia forces and torques of connecting rod using point masses
      NUR2XP=(-m21*L21DD(1)-m22*L22DD(1)-m23*L23DD(1))/2
     1     -m24*L24DD(1)
C     NUR2XP=-M2*L24DD(1)
      NUR2YP=(-m21*L21DD(2)-m22*L22DD(2)-m23*L23DD(2))/2
     1     -m24*L24DD(2)
C     NUR2YP=-M2*L24DD(2)
      NUR2ZP=(-m21*L21DD(3)-m22*L22DD(3)-m23*L23DD(3))/2
     1     -m24*L24DD(3)
C     NUR2ZP=-M2*L24DD(3)
      NUR2XD=-m21*(L211(2)*L21DD1(3)-L211(3)*L21DD1(2))/2
     1     -m21*(L212(2)*L21DD2(3)-L212(3)*L21DD2(2))/2
     1     -m22*(L221(2)*L22DD1(3)-L221(3)*L22DD1(2))/2
     1     -m22*(L222(2)*L22DD2(3)-L222(3)*L22DD2(2))/2
     1     -m23*(L231(2)*L23DD1(3)-L231(3)*L23DD1(2))/2
     1     -m23*(L232(2)*L23DD2(3)-L232(3)*L23DD2(2))/2
     1     -m24*(L24(2)*L24DD(3)-L24(3)*L24DD(2))
      NUR2YD=-m21*(L211(3)*L21DD1(1)-L211(1)*L21DD1(3))/2
     1     -m21*(L212(3)*L21DD2(1)-L212(1)*L21DD2(3))/2
     1     -m22*(L221(3)*L22DD1(1)-L221(1)*L22DD1(3))/2
     1     -m22*(L222(3)*L22DD2(1)-L222(1)*L22DD2(3))/2
     1     -m23*(L231(3)*L23DD1(1)-L231(1)*L23DD1(3))/2
     1     -m23*(L232(3)*L23DD2(1)-L232(1)*L23DD2(3))/2
     1     -m24*(L24(3)*L24DD(1)-L24(1)*L24DD(3))
      NUR2ZD=-m21*(L211(1)*L21DD1(2)-L211(2)*L21DD1(1))/2
     1     -m21*(L212(1)*L21DD2(2)-L212(2)*L21DD2(1))/2
     1     -m22*(L221(1)*L22DD1(2)-L221(2)*L22DD1(1))/2
     1     -m22*(L222(1)*L22DD2(2)-L222(2)*L22DD2(1))/2
     1     -m23*(L231(1)*L23DD1(2)-L231(2)*L23DD1(1))/2
     1     -m23*(L232(1)*L23DD2(2)-L232(2)*L23DD2(1))/2
     1     -m24*(L24(1)*L24DD(2)-L24(2)*L24DD(1))
      px(1)=-L11DD(1)
      px(2)=-L12DD(1)
      px(3)=-L13DD(1)
      px(4)=-L14DD(1)
      px(5)=-L21DD(1)
      px(6)=-L22DD(1)
      px(7)=-L23DD(1)
      px(8)=-L24DD(1)
      px(9)=0.0
          py(1)=-L11DD(2)
          py(2)=-L12DD(2)
          py(3)=-L13DD(2)
          py(4)=-L14DD(2)
          py(5)=-L21DD(2)
          py(6)=-L22DD(2)
          py(7)=-L23DD(2)
          py(8)=-L24DD(2)
          py(9)=M3*S4DD*SIN(ALP4)
      pz(1)=-L11DD(3)
      pz(2)=-L12DD(3)
      pz(3)=-L13DD(3)
      pz(4)=-L14DD(3)
      pz(5)=-L21DD(3)
      pz(6)=-L22DD(3)
      pz(7)=-L23DD(3)
      pz(8)=-L24DD(3)
      pz(9)=M3*S4DD*COS(ALP4)
      qx(1)=-(L111(2)*L11DD1(3)-L111(3)*L11DD1(2))/2
     1     -(L112(2)*L11DD2(3)-L112(3)*L11DD2(2))/2
      qx(2)=-(L121(2)*L12DD1(3)-L121(3)*L12DD1(2))/2
     1     -(L122(2)*L12DD2(3)-L122(3)*L12DD2(2))/2
      qx(3)=-(L131(2)*L13DD1(3)-L131(3)*L13DD1(2))/2
     1     -(L132(2)*L13DD2(3)-L132(3)*L13DD2(2))/2
      qx(4)=-(L14(2)*L14DD(3)-L14(3)*L14DD(2))
      qx(5)=-(L211(2)*L21DD1(3)-L211(3)*L21DD1(2))/2
     1     -(L212(2)*L21DD2(3)-L212(3)*L21DD2(2))/2
      qx(6)=-(L221(2)*L22DD1(3)-L221(3)*L22DD1(2))/2
     1     -(L222(2)*L22DD2(3)-L222(3)*L22DD2(2))/2
      qx(7)=-(L231(2)*L23DD1(3)-L231(3)*L23DD1(2))/2
     1     -(L232(2)*L23DD2(3)-L232(3)*L23DD2(2))/2
      qx(8)=-(L24(2)*L24DD(3)-L24(3)*L24DD(2))
      qx(9)=0.0
          qy(1)=-(L111(3)*L11DD1(1)-L111(1)*L11DD1(3))/2
     1         -(L112(3)*L11DD2(1)-L112(1)*L11DD2(3))/2
          qy(2)=-(L121(3)*L12DD1(1)-L121(1)*L12DD1(3))/2
     1         -(L122(3)*L12DD2(1)-L122(1)*L12DD2(3))/2
          qy(3)=-(L131(3)*L13DD1(1)-L131(1)*L13DD1(3))/2
     1         -(L132(3)*L13DD2(1)-L132(1)*L13DD2(3))/2
          qy(4)=-(L14(3)*L14DD(1)-L14(1)*L14DD(3))
          qy(5)=-(L211(3)*L21DD1(1)-L211(1)*L21DD1(3))/2
     1         -(L212(3)*L21DD2(1)-L212(1)*L21DD2(3))/2
          qy(6)=-(L221(3)*L22DD1(1)-L221(1)*L22DD1(3))/2
     1         -(L222(3)*L22DD2(1)-L222(1)*L22DD2(3))/2
          qy(7)=-(L231(3)*L23DD1(1)-L231(1)*L23DD1(3))/2
     1         -(L232(3)*L23DD2(1)-L232(1)*L23DD2(3))/2
          qy(8)=-(L24(3)*L24DD(1)-L24(1)*L24DD(3))
          qy(9)=A4*fz(9)
      qz(1)=-(L111(1)*L11DD1(2)-L111(2)*L11DD1(1))/2
     1     -(L112(1)*L11DD2(2)-L112(2)*L11DD2(1))/2
      qz(2)=-(L121(1)*L12DD1(2)-L121(2)*L12DD1(1))/2
     1     -(L122(1)*L12DD2(2)-L122(2)*L12DD2(1))/2
      qz(3)=-(L131(1)*L13DD1(2)-L131(2)*L13DD1(1))/2
     1     -(L132(1)*L13DD2(2)-L132(2)*L13DD2(1))/2
      qz(4)=-(L14(1)*L14DD(2)-L14(2)*L14DD(1))
      qz(5)=-(L211(1)*L21DD1(2)-L211(2)*L21DD1(1))/2
     1     -(L212(1)*L21DD2(2)-L212(2)*L21DD2(1))/2
      qz(6)=-(L221(1)*L22DD1(2)-L221(2)*L22DD1(1))/2
     1     -(L222(1)*L22DD2(2)-L222(2)*L22DD2(1))/2
      qz(7)=-(L231(1)*L23DD1(2)-L231(2)*L23DD1(1))/2
     1     -(L232(1)*L23DD2(2)-L232(2)*L23DD2(1))/2
      qz(8)=-(L24(1)*L24DD(2)-L24(2)*L24DD(1))
      qz(9)=A4*fy(9)
      DO 30 K=1,4
      fx(K)=TM1R(1,1)*px(K)+TM1R(1,2)*py(K)+TM1R(1,3)*pz(K)
      fy(K)=TM1R(2,1)*px(K)+TM1R(2,2)*py(K)+TM1R(2,3)*pz(K)
      fz(K)=TM1R(3,1)*px(K)+TM1R(3,2)*py(K)+TM1R(3,3)*pz(K)
      tx(K)=TM1R(1,1)*qx(K)+TM1R(1,2)*qy(K)+TM1R(1,3)*qz(K)
      ty(K)=TM1R(2,1)*qx(K)+TM1R(2,2)*qy(K)+TM1R(2,3)*qz(K)
      tz(K)=TM1R(3,1)*qx(K)+TM1R(3,2)*qy(K)+TM1R(3,3)*qz(K)
   30 CONTINUE
      DO 40 K1=5,8
      fx(K1)=TM1L2R(1,1)*px(K1)+TM1L2R(1,2)*py(K1)+TM1L2R(1,3)*pz(K1)
      fy(K1)=TM1L2R(2,1)*px(K1)+TM1L2R(2,2)*py(K1)+TM1L2R(2,3)*pz(K1)
      fz(K1)=TM1L2R(3,1)*px(K1)+TM1L2R(3,2)*py(K1)+TM1L2R(3,3)*pz(K1)
      tx(K1)=TM1L2R(1,1)*qx(K1)+TM1L2R(1,2)*qy(K1)+TM1L2R(1,3)*qz(K1)
      ty(K1)=TM1L2R(2,1)*qx(K1)+TM1L2R(2,2)*qy(K1)+TM1L2R(2,3)*qz(K1)
      tz(K1)=TM1L2R(3,1)*qx(K1)+TM1L2R(3,2)*qy(K1)+TM1L2R(3,3)*qz(K1)
   40 CONTINUE
      fx(9)=M4R(1,1)*px(9)+M4R(1,2)*py(9)+M4R(1,3)*pz(9)
      fy(9)=M4R(2,1)*px(9)+M4R(2,2)*py(9)+M4R(2,3)*pz(9)
      fz(9)=M4R(3,1)*px(9)+M4R(3,2)*py(9)+M4R(3,3)*pz(9)
      tx(9)=M4R(1,1)*qx(9)+M4R(1,2)*qy(9)+M4R(1,3)*qz(9)
      ty(9)=M4R(2,1)*qx(9)+M4R(2,2)*qy(9)+M4R(2,3)*qz(9)
      tz(9)=M4R(3,1)*qx(9)+M4R(3,2)*qy(9)+M4R(3,3)*qz(9)
      f3y(5)=-(fy(5)+tz(5)/A2)
      f3y(6)=-(fy(6)+tz(6)/A2)
      f3y(7)=-(fy(7)+tz(7)/A2)
      f3y(8)=-(fy(8)+tz(8)/A2)
          f3z(5)=-(fz(5)+ty(5)/A2)
          f3z(6)=-(fz(6)+ty(6)/A2)
          f3z(7)=-(fz(7)+ty(7)/A2)
          f3z(8)=-(fz(8)+ty(8)/A2)
      f3x(5)=cos(THT3)*f3y(5)/sin(THT3)
      f3x(6)=cos(THT3)*f3y(6)/sin(THT3)
      f3x(7)=cos(THT3)*f3y(7)/sin(THT3)
      f3x(7)=cos(THT3)*f3y(7)/sin(THT3)
      f3x(9)=fz(9)/sin(THT3)
      f4x(5)=(sin(ETA3)*f3z(5)-cos(THT3)*cos(ETA3)*f3x(5)
     1        -sin(THT3)*cos(ETA3)*f3y(5))
      f4x(6)=(sin(ETA3)*f3z(6)-cos(THT3)*cos(ETA3)*f3x(6)
     1        -sin(THT3)*cos(ETA3)*f3y(6))
      f4x(7)=(sin(ETA3)*f3z(7)-cos(THT3)*cos(ETA3)*f3x(7)
     1        -sin(THT3)*cos(ETA3)*f3y(7))
      f4x(8)=(sin(ETA3)*f3z(8)-cos(THT3)*cos(ETA3)*f3x(8)
     1        -sin(THT3)*cos(ETA3)*f3y(8))
      f4x(9)=(-cos(THT3)*cos(ETA3)*f3x(9)-fx(9))
          f4y(5)=-(cos(ETA3)*f3z(5)+cos(THT3)*sin(ETA3)*f3x(5)
     1            +sin(THT3)*sin(ETA3)*f3y(5))
          f4y(6)=-(cos(ETA3)*f3z(6)+cos(THT3)*sin(ETA3)*f3x(6)
     1            +sin(THT3)*sin(ETA3)*f3y(6))
          f4y(7)=-(cos(ETA3)*f3z(7)+cos(THT3)*sin(ETA3)*f3x(7)
     1            +sin(THT3)*sin(ETA3)*f3y(7))
          f4y(8)=-(cos(ETA3)*f3z(8)+cos(THT3)*sin(ETA3)*f3x(8)
     1            +sin(THT3)*sin(ETA3)*f3y(8))
          f4y(9)=(cos(THT3)*sin(ETA3)*f3x(9)+fy(9))
      t4x(9)=T4I
      t4y(9)=T4J
      t4z(9)=T4K
      f2x(5)=((-f3x(5)-fx(5))*cos(THT2)*cos(ETA2)+(f3y(5)+fy(5))
     1        *sin(THT2)-ty(5)*sin(ETA2)*cos(THT2)/A2)
      f2x(6)=((-f3x(6)-fx(6))*cos(THT2)*cos(ETA2)+(f3y(6)+fy(6))
     1        *sin(THT2)-ty(6)*sin(ETA2)*cos(THT2)/A2)
      f2x(7)=((-f3x(7)-fx(7))*cos(THT2)*cos(ETA2)+(f3y(7)+fy(7))
     1        *sin(THT2)-ty(7)*sin(ETA2)*cos(THT2)/A2)
      f2x(8)=((-f3x(8)-fx(8))*cos(THT2)*cos(ETA2)+(f3y(8)+fy(8))
     1        *sin(THT2)-ty(8)*sin(ETA2)*cos(THT2)/A2)
      f2x(9)=-f3x(9)*cos(THT2)*cos(ETA2)
          f2y(5)=((-f3x(5)-fx(5))*sin(THT2)*cos(ETA2)-(f3y(5)+fy(5))
     1            *cos(THT2)-ty(5)*sin(ETA2)*sin(THT2)/A2)
          f2y(6)=((-f3x(6)-fx(6))*sin(THT2)*cos(ETA2)-(f3y(6)+fy(6))
     1            *cos(THT2)-ty(6)*sin(ETA2)*sin(THT2)/A2)
          f2y(7)=((-f3x(7)-fx(7))*sin(THT2)*cos(ETA2)-(f3y(7)+fy(7))
     1            *cos(THT2)-ty(5)*sin(ETA2)*sin(THT2)/A2)
          f2y(8)=((-f3x(8)-fx(8))*sin(THT2)*cos(ETA2)-(f3y(8)+fy(8))
     1            *cos(THT2)-ty(8)*sin(ETA2)*sin(THT2)/A2)
          f2y(9)=-f3x(9)*sin(THT2)*cos(ETA2)
      if (ABS(COS(ETA)).GT. ABS(SIN(ETA))) then
      f2z(5)=-(fz(5)+f3z(5)+f2y(5)*sin(THT2)*sin(ETA2)+
     1         f2x(5)*cos(THT2)*sin(ETA2))/cos(ETA2)
      f2z(6)=-(fz(6)+f3z(6)+f2y(6)*sin(THT2)*sin(ETA2)+
     1         f2x(6)*cos(THT2)*sin(ETA2))/cos(ETA2)
      f2z(7)=-(fz(7)+f3z(7)+f2y(7)*sin(THT2)*sin(ETA2)+
     1         f2x(7)*cos(THT2)*sin(ETA2))/cos(ETA2)
      f2z(8)=-(fz(8)+f3z(8)+f2y(8)*sin(THT2)*sin(ETA2)+
     1         f2x(8)*cos(THT2)*sin(ETA2))/cos(ETA2)
      f2z(9)=-(f2y(9)*sin(THT2)*sin(ETA2)+
     1         f2x(9)*cos(THT2)*sin(ETA2))/cos(ETA2)
      else
      f2z(5)=(fz(5)+f3z(5)+f2y(5)*sin(THT2)*cos(ETA2)+
     1         f2x(5)*cos(THT2)*cos(ETA2))/sin(ETA2)
      f2z(6)=(fz(6)+f3z(6)+f2y(6)*sin(THT2)*cos(ETA2)+
     1         f2x(6)*cos(THT2)*cos(ETA2))/sin(ETA2)
      f2z(7)=(fz(7)+f3z(7)+f2y(7)*sin(THT2)*cos(ETA2)+
     1         f2x(7)*cos(THT2)*cos(ETA2))/sin(ETA2)
      f2z(8)=(fz(8)+f3z(8)+f2y(8)*sin(THT2)*cos(ETA2)+
     1         f2x(8)*cos(THT2)*cos(ETA2))/sin(ETA2)
      f2z(9)=(f2y(9)*sin(THT2)*cos(ETA2)+
     1         f2x(9)*cos(THT2)*cos(ETA2))/sin(ETA2)
      endif
      DO 50 K2=5,8
      f3x(K2)=M1L2R(1,1)*f3x(K2)+M1L2R(1,2)*f3y(K2)+M1L2R(1,3)*f3z(K2)
      f3y(K2)=M1L2R(2,1)*f3x(K2)+M1L2R(2,2)*f3y(K2)+M1L2R(2,3)*f3z(K2)
      f3z(K2)=M1L2R(3,1)*f3x(K2)+M1L2R(3,2)*f3y(K2)+M1L2R(3,3)*f3z(K2)
   50 CONTINUE
      DO 60 K3=5,8
      f2x(K3)=M1R(1,1)*f2x(K3)+M1R(1,2)*f2y(K3)+M1R(1,3)*f2z(K3)
      f2y(K3)=M1R(2,1)*f2x(K3)+M1R(2,2)*f2y(K3)+M1R(2,3)*f2z(K3)
      f2z(K3)=M1R(3,1)*f2x(K3)+M1R(3,2)*f2y(K3)+M1R(3,3)*f2z(K3)
   60 CONTINUE
      DO 70 K4=5,8
      f4x(K4)=TM4R(1,1)*f4x(K4)+TM4R(1,2)*f4y(K4)
      f4y(K4)=TM4R(2,1)*f4x(K4)+TM4R(2,2)*f4y(K4)
      f4z(K4)=TM4R(3,1)*f4x(K4)+TM4R(3,2)*f4y(K4)
   70 CONTINUE
      t4x(9)=TM4R(1,1)*t4x(9)+TM4R(1,2)*t4y(9)+TM4R(1,3)*t4z(9)
      t4y(9)=TM4R(2,1)*t4x(9)+TM4R(2,2)*t4y(9)+TM4R(2,3)*t4z(9)
      t4z(9)=TM4R(3,1)*t4x(9)+TM4R(3,2)*t4y(9)+TM4R(3,3)*t4z(9)
      f1z(1)=-fz(1)
      f1z(2)=-fz(2)
      f1z(3)=-fz(3)
      f1z(4)=-fz(4)
      f1z(5)=-f2z(5)
      f1z(6)=-f2z(6)
      f1z(7)=-f2z(7)
      f1z(8)=-f2z(8)
      f1z(9)=-f2z(9)
      f1x(1)=(-fx(1)*cos(THT1)+fy(1)*sin(THT1))
      f1x(2)=(-fx(2)*cos(THT1)+fy(2)*sin(THT1))
      f1x(3)=(-fx(3)*cos(THT1)+fy(3)*sin(THT1))
      f1x(4)=(-fx(4)*cos(THT1)+fy(4)*sin(THT1))
      f1x(5)=(-f2x(5)*cos(THT1)+f2y(5)*sin(THT1))
      f1x(6)=(-f2x(6)*cos(THT1)+f2y(6)*sin(THT1))
      f1x(7)=(-f2x(7)*cos(THT1)+f2y(7)*sin(THT1))
      f1x(8)=(-f2x(8)*cos(THT1)+f2y(8)*sin(THT1))
      f1x(9)=(-f2x(9)*cos(THT1)+f2y(9)*sin(THT1))
      f1y(1)=-(fx(1)*sin(THT1)+fy(1)*cos(THT1))
      f1y(2)=-(fx(2)*sin(THT1)+fy(2)*cos(THT1))
      f1y(3)=-(fx(3)*sin(THT1)+fy(3)*cos(THT1))
      f1y(4)=-(fx(4)*sin(THT1)+fy(4)*cos(THT1))
      f1y(5)=-(f2x(5)*sin(THT1)+f2y(5)*cos(THT1))
      f1y(6)=-(f2x(6)*sin(THT1)+f2y(6)*cos(THT1))
      f1y(7)=-(f2x(7)*sin(THT1)+f2y(7)*cos(THT1))
      f1y(8)=-(f2x(8)*sin(THT1)+f2y(8)*cos(THT1))
      f1y(9)=-(f2x(9)*sin(THT1)+f2y(9)*cos(THT1))
      t1z(1)=(f1y(1)*A1*cos(THT1)-f1x(1)*A1*sin(THT1)-tz(1))
      t1z(2)=(f1y(2)*A1*cos(THT1)-f1x(2)*A1*sin(THT1)-tz(2))
      t1z(3)=(f1y(3)*A1*cos(THT1)-f1x(3)*A1*sin(THT1)-tz(3))
      t1z(4)=(f1y(4)*A1*cos(THT1)-f1x(4)*A1*sin(THT1)-tz(4))
      t1z(5)=(f1y(5)*A1*cos(THT1)-f1x(5)*A1*sin(THT1))
      t1z(6)=(f1y(6)*A1*cos(THT1)-f1x(6)*A1*sin(THT1))
      t1z(7)=(f1y(7)*A1*cos(THT1)-f1x(7)*A1*sin(THT1))
      t1z(8)=(f1y(8)*A1*cos(THT1)-f1x(8)*A1*sin(THT1))
      t1z(9)=(f1y(9)*A1*cos(THT1)-f1x(9)*A1*sin(THT1))
      t1x(1)=(-f1y(1)*S1-tx(1)*cos(THT1)+f1z(1)*A1+
     1        ty(1)*sin(THT1))
      t1x(2)=(-f1y(2)*S1-tx(2)*cos(THT1)+f1z(2)*A1+
     1        ty(2)*sin(THT1))
      t1x(3)=(-f1y(3)*S1-tx(3)*cos(THT1)+f1z(3)*A1+
     1        ty(3)*sin(THT1))
      t1x(4)=(-f1y(4)*S1-tx(4)*cos(THT1)+f1z(4)*A1+
     1        ty(4)*sin(THT1))
      t1x(5)=t1z(5)*A1-f1y(5)*S1
      t1x(6)=t1z(6)*A1-f1y(6)*S1
      t1x(7)=t1z(7)*A1-f1y(7)*S1
      t1x(8)=t1z(8)*A1-f1y(8)*S1
      t1x(9)=t1z(9)*A1-f1y(9)*S1
      t1y(1)=f1x(1)*S1-f1z(1)*A1-tx(1)*sin(THT1)-ty(1)*cos(THT1)
      t1y(2)=f1x(2)*S1-f1z(2)*A1-tx(2)*sin(THT1)-ty(2)*cos(THT1)
      t1y(3)=f1x(3)*S1-f1z(3)*A1-tx(3)*sin(THT1)-ty(3)*cos(THT1)
      t1y(4)=f1x(4)*S1-f1z(4)*A1-tx(4)*sin(THT1)-ty(4)*cos(THT1)
      t1y(5)=f1x(5)*S1-f1z(5)*A1
      t1y(6)=f1x(6)*S1-f1z(6)*A1
      t1y(7)=f1x(7)*S1-f1z(7)*A1
      t1y(8)=f1x(8)*S1-f1z(8)*A1
      t1y(9)=f1x(9)*S1-f1z(9)*A1
      CALL SQUARE (fx,fxsq)
      CALL SQUARE (fy,fysq)
      CALL SQUARE (fz,fzsq)
      CALL SQUARE (tx,txsq)
      CALL SQUARE (ty,tysq)
      CALL SQUARE (tz,tzsq)
      CALL SQUARE (f1x,f1xsq)
      CALL SQUARE (f1y,f1ysq)
      CALL SQUARE (f1z,f1zsq)
      CALL SQUARE (t1x,t1xsq)
      CALL SQUARE (t1y,t1ysq)
      CALL SQUARE (t1z,t1zsq)
      CALL SQUARE (f2x,f2xsq)
      CALL SQUARE (f2y,f2ysq)
      CALL SQUARE (f2z,f2zsq)
      CALL SQUARE (f3x,f3xsq)
      CALL SQUARE (f3y,f3ysq)
      CALL SQUARE (f3z,f3zsq)
      CALL SQUARE (f4x,f4xsq)
      CALL SQUARE (f4y,f4ysq)
      CALL SQUARE (t4x,t4xsq)
      CALL SQUARE (t4y,t4ysq)
      CALL SQUARE (t4z,t4zsq)
      C1=37*(M1**2)*(A1**2)*(THT1D**4)
      C2=C1*(A1**2)
      C3=C1*(BL**2)
      DO 80 I1=1,9
      DO 90 J1=1,9
      fsq(I1,J1)=(fxsq(I1,J1)+fysq(I1,J1)+fzsq(I1,J1))/C1
      tsq(I1,J1)=(txsq(I1,J1)+tysq(I1,J1)+tzsq(I1,J1))/C2
      rsq(I1,J1)=(f1xsq(I1,J1)+f1ysq(I1,J1)+f1zsq(I1,J1)
     1      +f2xsq(I1,J1)+f2ysq(I1,J1)+f2zsq(I1,J1)
     1      +f3xsq(I1,J1)+f3ysq(I1,J1)+f3zsq(I1,J1)
     1      +f4xsq(I1,J1)+f4ysq(I1,J1)+f4zsq(I1,J1))/C1
      msq(I1,J1)=(t1xsq(I1,J1)+t1ysq(I1,J1)
     1      +t4xsq(I1,J1)+t4ysq(I1,J1)+t4zsq(I1,J1))/C3
      t0sq(I1,J1)=t1zsq(I1,J1)/C2
      F(I1,J1)=W1*fsq(I1,J1)+W2*tsq(I1,J1)+W3*rsq(I1,J1)
     1      +W4*msq(I1,J1)+W5*t0sq(I1,J1)
      OF(I1,J1)=OF(I1,J1)+F(I1,J1)
      h(I1,J1)=2*OF(I1,J1)
   90 CONTINUE
   80 CONTINUE
C     write (6,1) F(1,1)
C     write (6,1) OF(6,8),OF(8,6),OF(9,9)
C     write (6,1) fx(1),fx(2),fx(3)
C     write (6,1) L11DD(1),L12DD(1),L13DD(1)
C     write (6,1) fx(4),fx(5),fx(6)
C     write (6,1) fx(7),fx(8),fx(9)
C     write (6,1) fxsq(1,1),fxsq(1,2),fxsq(1,3)
C     write (6,1) fxsq(1,4),fxsq(1,5),fxsq(1,6)
C     write (6,1) tsq(1,7),tsq(1,8),tsq(1,9)
C     write (6,1) NUR2XP,NUR2YP,NUR2ZP
C     write (6,1) M1L2R2P(1),M1L2R2P(2),M1L2R2P(3)
      ELSE
      THT2=THT2+DELTA(1)
      ETA2=ETA2+DELTA(2)
      THT3=THT3+DELTA(3)
      ETA3=ETA3+DELTA(4)
      S4=S4+DELTA(5)
      I=I+1
      GO TO 10
      ENDIF
      ELSE
C     WRITE(6,2) I                                                      ! D052
C     STOP                                                              ! D052
      ISTAT=1                                                           ! D052
      FAILDG=TH1                                                        ! D052
      RETURN                                                            ! D052
      ENDIF
C   1 FORMAT('SLIDER VELOCITY=',F10.5,2X,'WHEN CRANK ANGLE='
C    1,F7.2,1X,'S1=',F7.2,1X,'NO OF ITERATIONS=',I3)
    1 FORMAT(3F20.5)
    2 FORMAT ('THE METHOD FAILS AFTER', I3, 'ITERATIONS')
C Determination of the objective function
      OBJFUN=0.0
      NUOBJFUN=0.0
      if (I3 .EQ. 2) then
      do 42 I4=1,9
      do 43 J4=1,9
      if (I4 .NE. J4) then
      F(I4,J4)=2.0*F(I4,J4)
      endif
      OBJFUN=OBJFUN+m(I4)*m(J4)*F(I4,J4)
      NUOBJFUN=NUOBJFUN+sol(I4)*sol(J4)*F(I4,J4)
   43 continue
   42 continue
      call dotprod(m,fx,mfx)
C     call dotprod(sol,fx,nufx)
      call dotprod(m,fy,mfy)
C     call dotprod(sol,fy,nufy)
      call dotprod(m,fz,mfz)
C     call dotprod(sol,fz,nufz)
      call dotprod(m,tx,mtx)
C     call dotprod(sol,tx,nutx)
      call dotprod(m,ty,mty)
C     call dotprod(sol,ty,nuty)
      call dotprod(m,tz,mtz)
C     call dotprod(sol,tz,nutz)
      call dotprod(m,f1x,mf1x)
C     call dotprod(sol,f1x,nuf1x)
      call dotprod(m,f1y,mf1y)
C     call dotprod(sol,f1y,nuf1y)
      call dotprod(m,f1z,mf1z)
C     call dotprod(sol,f1z,nuf1z)
      call dotprod(m,t1x,mt1x)
C     call dotprod(sol,t1x,nut1x)
      call dotprod(m,t1y,mt1y)
C     call dotprod(sol,t1y,nut1y)
      call dotprod(m,t1z,mt1z)
C     call dotprod(sol,t1z,nut1z)
      call dotprod(m,f2x,mf2x)
C     call dotprod(sol,f2x,nuf2x)
      call dotprod(m,f2y,mf2y)
C     call dotprod(sol,f2y,nuf2y)
      call dotprod(m,f2z,mf2z)
C     call dotprod(sol,f2z,nuf2z)
      call dotprod(m,f3x,mf3x)
C     call dotprod(sol,f3x,nuf3x)
      call dotprod(m,f3y,mf3y)
C     call dotprod(sol,f3y,nuf3y)
      call dotprod(m,f3z,mf3z)
C     call dotprod(sol,f3z,nuf3z)
      call dotprod(m,f4x,mf4x)
C     call dotprod(sol,f4x,nuf4x)
      call dotprod(m,f4y,mf4y)
C     call dotprod(sol,f4y,nuf4y)
      call dotprod(m,t4x,mt4x)
C     call dotprod(sol,t4x,nut4x)
      call dotprod(m,t4y,mt4y)
C     call dotprod(sol,t4y,nut4y)
      call dotprod(m,t4z,mt4z)
C     call dotprod(sol,t4z,nut4z)
      shf=(mfx**2+mfy**2+mfz**2)**0.5
      sht=(mtx**2+mty**2+mtz**2)**0.5
      brf=((mf1x+mf2x+mf3x+mf4x)**2
     1   +(mf1y+mf2y+mf3y+mf4y)**2
     1   +(mf1z+mf2z+mf3z)**2)**0.5
      brt=((mt1x+mt4x)**2
     1   +(mt1y+mt4y)**2
     1   +(mt1z+mt4z)**2)**0.5
      int=mt1z
C     write (6,*) OBJFUN,NUOBJFUN
C     write (6,*) mfx,nufx
C     write (6,*) mfy,nufy
C     write (6,*) mfz,nufz
C     write (6,*) f1x(3),f1x(1),m(3)*fx(3),sol(3)*fx(3)
      nufx=0.0
      nufy=0.0
      nufz=0.0
      nutx=0.0
      nuty=0.0
      nutz=0.0
      nuf1x=0.0
      nuf1y=0.0
      nuf1z=0.0
      nut1x=0.0
      nut1y=0.0
      nut1z=0.0
      nuf2x=0.0
      nuf2y=0.0
      nuf2z=0.0
      nuf3x=0.0
      nuf3y=0.0
      nuf3z=0.0
      nuf4x=0.0
      nuf4y=0.0
      nut4x=0.0
      nut4y=0.0
      nut4z=0.0
      do 233 i10=1,9
      nufx=nufx+sol(i10)*fx(i10)
      nufy=nufy+sol(i10)*fy(i10)
      nufz=nufz+sol(i10)*fz(i10)
      nutx=nutx+sol(i10)*tx(i10)
      nuty=nuty+sol(i10)*ty(i10)
      nutz=nutz+sol(i10)*tz(i10)
      nuf1x=nuf1x+sol(i10)*f1x(i10)
      nuf1y=nuf1y+sol(i10)*f1y(i10)
      nuf1z=nuf1z+sol(i10)*f1z(i10)
      nut1x=nut1x+sol(i10)*t1x(i10)
      nut1y=nut1y+sol(i10)*t1y(i10)
      nut1z=nut1z+sol(i10)*t1z(i10)
      nuf2x=nuf2x+sol(i10)*f2x(i10)
      nuf2y=nuf2y+sol(i10)*f2y(i10)
      nuf2z=nuf2z+sol(i10)*f2z(i10)
      nuf3x=nuf3x+sol(i10)*f3x(i10)
      nuf3y=nuf3y+sol(i10)*f3y(i10)
      nuf3z=nuf3z+sol(i10)*f3z(i10)
      nuf4x=nuf4x+sol(i10)*f4x(i10)
      nuf4y=nuf4y+sol(i10)*f4y(i10)
      nut4x=nut4x+sol(i10)*t4x(i10)
      nut4y=nut4y+sol(i10)*t4y(i10)
      nut4z=nut4z+sol(i10)*t4z(i10)
  233 continue
      nushf=((nufx**2)+(nufy**2)+(nufz**2))**0.5
      nusht=(nutx**2+nuty**2+nutz**2)**0.5
      nubrf=((nuf1x+nuf2x+nuf3x+nuf4x)**2
     1     +(nuf1y+nuf2y+nuf3y+nuf4y)**2
     1     +(nuf1z+nuf2z+nuf3z)**2)**0.5
      nubrt=((nut1x+nut4x)**2
     1     +(nut1y+nut4y)**2
     1     +(nut1z+nut4z)**2)**0.5
      nuint=nut1z
      DOBJFUN=(OBJFUN-NUOBJFUN)*100/OBJFUN
      dshf=(shf-nushf)*100/shf
      dsht=(sht-nusht)*100/sht
      dbrf=(brf-nubrf)*100/brf
      dbrt=(brt-nubrt)*100/brt
      dint=(int-nuint)*100/int
C     write(6,*) TH1,dint                                               ! D053
      TABLE(J,1)=OBJFUN                                                 ! D053
      TABLE(J,2)=NUOBJFUN                                               ! D053
      TABLE(J,3)=shf                                                    ! D053
      TABLE(J,4)=nushf                                                  ! D053
      TABLE(J,5)=sht                                                    ! D053
      TABLE(J,6)=nusht                                                  ! D053
      TABLE(J,7)=brf                                                    ! D053
      TABLE(J,8)=nubrf                                                  ! D053
      TABLE(J,9)=brt                                                    ! D053
      TABLE(J,10)=nubrt                                                 ! D053
      TABLE(J,11)=int                                                   ! D053
      TABLE(J,12)=nuint                                                 ! D053
      endif
  400 CONTINUE
C     write (6,1) OF(6,8),OF(8,6),OF(9,9)
      call qprog (nvar,ncon,neq,aa,lda,b,gg,h,ldh,diag,sol,
     1 nact,iact,alamda)
      call umach (2,nout)
      CALL QPSTAT_GET(IQP)                                              ! D052
      IF (IQP.NE.0) THEN                                                ! D052
      ISTAT=3                                                           ! D052
      RETURN                                                            ! D052
      ENDIF                                                             ! D052
      IF (I3.EQ.1) THEN                                                 ! D053
      DO 44 I4=1,9                                                      ! D053
      DO 44 J4=1,9                                                      ! D053
   44 HOUT(I4,J4)=h(I4,J4)                                              ! D053
      DIAGO=diag                                                        ! D053
      ENDIF                                                             ! D053
      IF (USESOL.NE.0) THEN                                             ! D055
      DO 45 I4=1,9                                                      ! D055
   45 sol(I4)=SOLIN(I4)                                                 ! D055
      ENDIF                                                             ! D055
      IF (I3.EQ.1) THEN                                                 ! D151
      DO 47 I4=1,9                                                      ! D151
   47 SOLAFT(I4)=sol(I4)                                                ! D151
      ENDIF                                                             ! D151
C     write (nout,999) (sol(k),k=1,nvar)
C 999 format ('the solution vector is',/,'sol=(',9F12.6,')')
C     write(6,*) m(1),m(2),m(3),m(4),m(5),m(6),m(7),m(8),m(9)
   41 continue
      NUI1X=(Y1**2)*sol(2)+(Z1**2)*sol(3)
      NUI2X=(Y2**2)*sol(6)+(Z2**2)*sol(7)
      NUI1Y=(X1**2)*sol(1)+(Z1**2)*sol(3)
      NUI2Y=(X2**2)*sol(5)+(Z2**2)*sol(7)
      NUI1Z=(X1**2)*sol(1)+(Y1**2)*sol(2)
      NUI2Z=(X2**2)*sol(5)+(Y2**2)*sol(6)
C     write(6,*) I1X,NUI1X                                              ! D053
      INERT(1,1)=I1X                                                    ! D053
      INERT(1,2)=NUI1X                                                  ! D053
      INERT(2,1)=I1Y                                                    ! D053
      INERT(2,2)=NUI1Y                                                  ! D053
      INERT(3,1)=I1Z                                                    ! D053
      INERT(3,2)=NUI1Z                                                  ! D053
      INERT(4,1)=I2X                                                    ! D053
      INERT(4,2)=NUI2X                                                  ! D053
      INERT(5,1)=I2Y                                                    ! D053
      INERT(5,2)=NUI2Y                                                  ! D053
      INERT(6,1)=I2Z                                                    ! D053
      INERT(6,2)=NUI2Z                                                  ! D053
      DO 46 I4=1,9                                                      ! D053
   46 SOLOUT(I4)=sol(I4)                                                ! D053
C     write(6,*) I1Y,NUI1Y
C     write(6,*) I1Z,NUI1Z
C     write(6,*) I2X,NUI2X
C     write(6,*) I2Y,NUI2Y
C     write(6,*) I2z,NUI2Z
C     STOP                                                              ! D052
      RETURN                                                            ! D052
C
      END
