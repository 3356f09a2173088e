C     ..................................................................GMTR  10
C                                                                       GMTR  20
C        SUBROUTINE GMTRA                                               GMTR  40
C                                                                       GMTR  50
C        PURPOSE                                                        GMTR  60
C           TRANSPOSE A GENERAL MATRIX                                  GMTR  70
C                                                                       GMTR  80
C        USAGE                                                          GMTR  90
C           CALL GMTRA(A,R,N,M)                                         GMTR 100
C                                                                       GMTR 110
C        DESCRIPTION OF PARAMETERS                                      GMTR 120
C           A - NAME OF MATRIX TO BE TRANSPOSED                         GMTR 130
C           R - NAME OF RESULTANT MATRIX                                GMTR 140
C           N - NUMBER OF ROWS OF A AND COLUMNS OF R                    GMTR 150
C           M - NUMBER OF COLUMNS OF A AND ROWS OF R                    GMTR 160
C                                                                       GMTR 170
C        REMARKS                                                        GMTR 180
C           MATRIX R CANNOT BE IN THE SAME LOCATION AS MATRIX A         GMTR 190
C           MATRICES A AND R MUST BE STORED AS GENERAL MATRICES         GMTR 200
C                                                                       GMTR 210
C        SUBROUTINES AND FUNCTION SUBPROGRAMS REQUIRED                  GMTR 220
C           NONE                                                        GMTR 230
C                                                                       GMTR 240
C        METHOD                                                         GMTR 250
C           TRANSPOSE N BY M MATRIX A TO FORM M BY N MATRIX R           GMTR 260
C                                                                       GMTR 270
C     ..................................................................GMTR 280
C                                                                       GMTR 285
      SUBROUTINE GMTRA(A,R,N,M)                                         GMTR 290
      DIMENSION A(1),R(1)                                               GMTR 300
C                                                                       GMTR 310
      IR=0                                                              GMTR 320
      DO 10 I=1,N                                                       GMTR 330
      IJ=I-N                                                            GMTR 340
      DO 10 J=1,M                                                       GMTR 350
      IJ=IJ+N                                                           GMTR 360
      IR=IR+1                                                           GMTR 370
   10 R(IR)=A(IJ)                                                       GMTR 380
      RETURN                                                            GMTR 390
      END                                                               GMTR 400
