C     J2 (von Mises) plasticity with linear isotropic hardening as an
C     Abaqus/Standard UMAT, written for the tests umat_*: PROPS(1) = E,
C     PROPS(2) = nu, PROPS(3) = initial yield stress, PROPS(4) =
C     hardening modulus H; STATEV(1) = equivalent plastic strain alpha
C     (NSTATV = 1). Radial return from the elastic trial stress and the
C     consistent tangent (de Souza Neto, Peric & Owen 2008, Boxes 7.3
C     and 7.4). SPD accumulates the plastic dissipation per unit volume.
      SUBROUTINE UMAT(STRESS,STATEV,DDSDDE,SSE,SPD,SCD,
     1 RPL,DDSDDT,DRPLDE,DRPLDT,
     2 STRAN,DSTRAN,TIME,DTIME,TEMP,DTEMP,PREDEF,DPRED,CMNAME,
     3 NDI,NSHR,NTENS,NSTATV,PROPS,NPROPS,COORDS,DROT,PNEWDT,
     4 CELENT,DFGRD0,DFGRD1,NOEL,NPT,LAYER,KSPT,KSTEP,KINC)
      IMPLICIT REAL*8(A-H,O-Z)
      CHARACTER*80 CMNAME
      DIMENSION STRESS(NTENS),STATEV(NSTATV),
     1 DDSDDE(NTENS,NTENS),DDSDDT(NTENS),DRPLDE(NTENS),
     2 STRAN(NTENS),DSTRAN(NTENS),TIME(2),PREDEF(1),DPRED(1),
     3 PROPS(NPROPS),COORDS(3),DROT(3,3),DFGRD0(3,3),DFGRD1(3,3)
      DIMENSION S(6), ANRM(6)
      E    = PROPS(1)
      ANU  = PROPS(2)
      SY0  = PROPS(3)
      H    = PROPS(4)
      G    = E/(2.D0*(1.D0+ANU))
      ALAM = E*ANU/((1.D0+ANU)*(1.D0-2.D0*ANU))
      BK   = ALAM + 2.D0*G/3.D0
C     Elastic stiffness and trial stress.
      DO I = 1, NTENS
        DO J = 1, NTENS
          DDSDDE(I,J) = 0.D0
        END DO
      END DO
      DO I = 1, NDI
        DO J = 1, NDI
          DDSDDE(I,J) = ALAM
        END DO
        DDSDDE(I,I) = ALAM + 2.D0*G
      END DO
      DO I = NDI+1, NTENS
        DDSDDE(I,I) = G
      END DO
      DO I = 1, NTENS
        DO J = 1, NTENS
          STRESS(I) = STRESS(I) + DDSDDE(I,J)*DSTRAN(J)
        END DO
      END DO
C     Deviator of the trial stress, its norm |s| (shears count twice).
      P = (STRESS(1) + STRESS(2) + STRESS(3))/3.D0
      SNRM2 = 0.D0
      DO I = 1, NTENS
        IF (I .LE. NDI) THEN
          S(I) = STRESS(I) - P
          SNRM2 = SNRM2 + S(I)**2
        ELSE
          S(I) = STRESS(I)
          SNRM2 = SNRM2 + 2.D0*S(I)**2
        END IF
      END DO
      SNRM = SQRT(SNRM2)
      QTR  = SQRT(1.5D0)*SNRM
      ALPHA = STATEV(1)
      SY   = SY0 + H*ALPHA
      PHI  = QTR - SY
      IF (.NOT. (PHI .GT. 1.D-13*SY)) RETURN
C     Plastic: radial return.
      DGAM = PHI/(3.D0*G + H)
      FAC  = 1.D0 - 3.D0*G*DGAM/QTR
      DO I = 1, NTENS
        ANRM(I) = S(I)/SNRM
        IF (I .LE. NDI) THEN
          STRESS(I) = FAC*S(I) + P
        ELSE
          STRESS(I) = FAC*S(I)
        END IF
      END DO
      STATEV(1) = ALPHA + DGAM
      SPD = SPD + DGAM*(SY + 0.5D0*H*DGAM)
C     Consistent tangent: 2 G FAC I_dev + 6 G^2 (DGAM/QTR - 1/(3G + H))
C     N (x) N + K 1 (x) 1, in Voigt form (I_dev's shear diagonal 1/2).
      C1 = 6.D0*G*G*(DGAM/QTR - 1.D0/(3.D0*G + H))
      DO I = 1, NTENS
        DO J = 1, NTENS
          DDSDDE(I,J) = C1*ANRM(I)*ANRM(J)
        END DO
      END DO
      DO I = 1, NDI
        DO J = 1, NDI
          DDSDDE(I,J) = DDSDDE(I,J) + BK - 2.D0*G*FAC/3.D0
        END DO
        DDSDDE(I,I) = DDSDDE(I,I) + 2.D0*G*FAC
      END DO
      DO I = NDI+1, NTENS
        DDSDDE(I,I) = DDSDDE(I,I) + G*FAC
      END DO
      RETURN
      END
