C     Drucker-Prager plasticity with cohesion hardening and
C     non-associative flow as an Abaqus/Standard UMAT, written for the
C     test umat_drucker_prager: the return mapping of qsmpm's
C     "Drucker-Prager" model (source/materials/drucker_prager.cc; de
C     Souza Neto, Peric & Owen 2008, Section 8.3.3) with the cone fitted
C     to Mohr-Coulomb in plane strain. PROPS(1) = E, PROPS(2) = nu,
C     PROPS(3) = cohesion c, PROPS(4) = friction angle phi and PROPS(5) =
C     dilatancy angle psi in degrees, PROPS(6) = hardening modulus H.
C     STATEV(1:NTENS) = the elastic strain (engineering shears, as
C     Abaqus's example UMATs keep EELAS), STATEV(NTENS+1) = the hardening
C     variable alpha (NSTATV = NTENS + 1). The stress is D : eps_e; a
C     dilatant flow changes the volume by its plastic part, which the
C     entry "Elastic strain state variable = 1" tells qsmpm's F-bar.
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
C     Tensors as their 6 components xx, yy, zz, xy, xz, yz (tensorial
C     shears); ONE the identity, E the trial strain's deviator.
      DIMENSION EPS(6), E(6), ANRM(6), ONE(6), SIG(6), EEL(6), C(6,6)
      DATA ONE /1.D0, 1.D0, 1.D0, 0.D0, 0.D0, 0.D0/
      PI   = 4.D0*ATAN(1.D0)
      YM   = PROPS(1)
      ANU  = PROPS(2)
      C0   = PROPS(3)
      H    = PROPS(6)
      G    = YM/(2.D0*(1.D0+ANU))
      BK   = YM/(3.D0*(1.D0-2.D0*ANU))
C     The plane-strain matching: eta = 3 tan(a) / sqrt(9 + 12 tan^2(a)),
C     xi = 3 / sqrt(9 + 12 tan^2(a)).
      T    = TAN(PROPS(4)*PI/180.D0)
      ETAF = 3.D0*T/SQRT(9.D0 + 12.D0*T*T)
      XIC  = 3.D0/SQRT(9.D0 + 12.D0*T*T)
      T    = TAN(PROPS(5)*PI/180.D0)
      ETAD = 3.D0*T/SQRT(9.D0 + 12.D0*T*T)
      ALPHA = STATEV(NTENS+1)
C     The trial elastic strain: the committed one plus the increment.
      DO K = 1, 6
        EPS(K) = 0.D0
      END DO
      DO K = 1, NTENS
        F = 1.D0
        IF (K .GT. NDI) F = 0.5D0
        EPS(K) = F*(STATEV(K) + DSTRAN(K))
      END DO
      TR = EPS(1) + EPS(2) + EPS(3)
      ENRM = 0.D0
      DO K = 1, 6
        E(K) = EPS(K) - TR/3.D0*ONE(K)
        F = 1.D0
        IF (K .GT. 3) F = 2.D0
        ENRM = ENRM + F*E(K)*E(K)
      END DO
      ENRM = SQRT(ENRM)
      PTR  = BK*TR
      SQJ2 = SQRT(2.D0)*G*ENRM
      CN   = C0 + H*ALPHA
      PHI  = SQJ2 + ETAF*PTR - XIC*CN
C     The tangent's coefficients: C = 2 G CD I_dev + CNN n x n
C     + CN1 n x 1 + C1N 1 x n + C11 1 x 1 (elastic: CD = 1, C11 = K).
      CD  = 1.D0
      CNN = 0.D0
      CN1 = 0.D0
      C1N = 0.D0
      C11 = BK
      DO K = 1, 6
        ANRM(K) = 0.D0
      END DO
      IF (.NOT. (PHI .GT. 1.D-13*(SQJ2 + ABS(ETAF*PTR) + XIC*CN))) THEN
        DO K = 1, 6
          SIG(K) = 2.D0*G*E(K) + PTR*ONE(K)
          EEL(K) = EPS(K)
        END DO
      ELSE
        A  = 1.D0/(G + BK*ETAF*ETAD + XIC*XIC*H)
        DG = PHI*A
        IF (SQJ2 - G*DG .GE. 0.D0 .OR. ETAF .EQ. 0.D0) THEN
C         Return to the cone.
          FAC = 1.D0 - G*DG/SQJ2
          P   = PTR - BK*ETAD*DG
          DO K = 1, 6
            SIG(K)  = FAC*2.D0*G*E(K) + P*ONE(K)
            EEL(K)  = FAC*E(K) + P/(3.D0*BK)*ONE(K)
            ANRM(K) = E(K)/ENRM
          END DO
          ALPHA = ALPHA + XIC*DG
          AA  = DG/(SQRT(2.D0)*ENRM)
          CD  = 1.D0 - AA
          CNN = 2.D0*G*(AA - G*A)
          CN1 = -SQRT(2.D0)*G*A*BK*ETAF
          C1N = -SQRT(2.D0)*G*A*BK*ETAD
          C11 = BK*(1.D0 - BK*ETAF*ETAD*A)
        ELSE
C         Return to the apex.
          BETA = XIC/ETAF
          ALV  = BETA
          IF (ETAD .GT. 0.D0) ALV = XIC/ETAD
          DEV  = (PTR - BETA*CN)/(ALV*BETA*H + BK)
          P    = PTR - BK*DEV
          DO K = 1, 6
            SIG(K) = P*ONE(K)
            EEL(K) = P/(3.D0*BK)*ONE(K)
          END DO
          ALPHA = ALPHA + ALV*DEV
          CD  = 0.D0
          C11 = BK*(1.D0 - BK/(BK + ALV*BETA*H))
        END IF
      END IF
C     The tangent by components: I_dev is delta_kl - 1/3 on the direct
C     components and 1/2 on the diagonal of the shears (d sigma_ij /
C     d gamma_ij = C_ijij for an engineering shear gamma = 2 eps_ij).
      DO K = 1, 6
        DO L = 1, 6
          D = 0.D0
          IF (K .LE. 3 .AND. L .LE. 3) D = -1.D0/3.D0
          IF (K .EQ. L) D = D + 1.D0
          IF (K .EQ. L .AND. K .GT. 3) D = 0.5D0
          C(K,L) = 2.D0*G*CD*D + CNN*ANRM(K)*ANRM(L)
     1      + CN1*ANRM(K)*ONE(L) + C1N*ONE(K)*ANRM(L)
     2      + C11*ONE(K)*ONE(L)
        END DO
      END DO
      DO K = 1, NTENS
        STRESS(K) = SIG(K)
        F = 1.D0
        IF (K .GT. NDI) F = 2.D0
        STATEV(K) = F*EEL(K)
        DO L = 1, NTENS
          DDSDDE(K,L) = C(K,L)
        END DO
      END DO
      STATEV(NTENS+1) = ALPHA
      RETURN
      END
