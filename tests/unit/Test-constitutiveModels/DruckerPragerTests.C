/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | mpmLbmFoam: material point + lattice Boltzmann
   \\    /   O peration     | soil-water interaction on OpenFOAM
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of mpmLbmFoam, distributed under the terms of the GNU
    General Public License version 3 or later, as OpenFOAM it builds on.


Description
    Test-constitutiveModels: DruckerPrager for the three fits (cone/apex,
    flow direction, closest point for psi = phi, rotation invariance, the
    fits touch the Mohr-Coulomb edges or reproduce its plane-strain
    failure).

\*---------------------------------------------------------------------------*/

#include "constitutiveModelsTest.H"

// * * * * * * * * * * * * * * * DruckerPrager  * * * * * * * * * * * * * * //

// c = 0: tensile states return to zero (every one for psi = 0,
// near-hydrostatic ones for psi > 0; see testMohrCoulombOrigin)
static void testDruckerPragerZero
(
    const DruckerPrager& dp,
    const std::string& tag,
    const scalar psi,
    Random& rnd
)
{
    scalar eZero = 0;
    label nZero = 0;
    for (label t = 0; t < 1000; ++t)
    {
        vector p(1e5*rnd.sample01<vector>());
        const bool hydro = (psi > 0);
        if (hydro)
        {
            p = 1e5*(vector::one + 0.1*rnd.sample01<vector>());
        }
        symmTensor s(transform(randomRotation(rnd), diagonal(p)));
        scalar ep = 0;
        dp.updateStress(symmTensor::zero, s, ep);
        eZero = max(eZero, maxMag(s));
        if (maxMag(s) == 0) ++nZero;
    }
    symmTensor s(Zero);
    scalar ep = 0;
    dp.updateStress(symmTensor::zero, s, ep);
    eZero = max(eZero, maxMag(s));
    check(eZero == 0 && ep == 0, tag + (psi > 0 ? " near-hydrostatic" :
        " every") + " tensile trial and the zero state return exactly"
        " to zero", eZero, 0);
}


static void testDruckerPragerSet
(
    const scalar c,
    const scalar phi,
    const scalar psi,
    const word& fit
)
{
    const std::string tag = "DP(" + fit + " c=" + num(c/1e3) + "kPa phi="
        + num(phi) + " psi=" + num(psi) + ")";
    const dictionary dict(makeDict(dpText(c, phi, psi, fit)));
    autoPtr<constitutiveModel> model = constitutiveModel::New("clay", dict);
    const DruckerPrager& dp = refCast<const DruckerPrager>(model());
    const scalar G = dp.G(), K = dp.K();
    const scalar S = max(100e3, c);
    const scalar tol = 1e-10;

    // Elastic trial unchanged
    {
        const symmTensor s0(-S, 1e3, 0, -S, -1e3, -1.1*S);
        const symmTensor dEps(1e-6, 0, 1e-6, -1e-6, 0, 0);
        symmTensor s(s0);
        scalar ep = 0;
        const DruckerPrager::returnRegion r = dp.update(dEps, s, ep);
        const symmTensor expect(s0 + dp.lambda()*tr(dEps)*I + 2*G*dEps);
        const scalar err = maxMag(s - expect)/S;
        check(r == DruckerPrager::elastic && err < 1e-15 && ep == 0,
            tag + " elastic trial unchanged", err, 1e-15);
    }

    // Random trials
    Random rnd(41);
    label counts[3] = {0, 0, 0};
    scalar eAdm = 0, eSurf = 0, eApex = 0, eFlow = 0, eRot = 0;
    bool ok = true;
    for (label t = 0; t < 10000; ++t)
    {
        const symmTensor trial
        (
            randomSymm(rnd, (t % 3 == 0 ? 0.2 : 1)*S)
          + (S*(rnd.sample01<scalar>() - 0.7))*I
        );
        symmTensor s(trial);
        scalar ep = 0;
        const DruckerPrager::returnRegion r =
            dp.update(symmTensor::zero, s, ep);
        ++counts[r];
        ok = ok && finite(s) && std::isfinite(ep) && ep >= 0;
        const scalar sc = max(maxMag(trial), S);
        const scalar f = dp.yieldFunction(s)/sc;
        eAdm = max(eAdm, f);
        if (r == DruckerPrager::cone)
        {
            eSurf = max(eSurf, mag(f));
            // Flow: D^-1(trial - s) = dGamma (s/(2 sqrt(J2)) + etaBar/3 I):
            // deviatoric part parallel to dev(s), volumetric/deviatoric
            // norm ratio sqrt(2) etaBar
            const symmTensor dS(trial - s);
            const symmTensor devEp(dev(dS)/(2*G));
            const scalar volEp = tr(dS)/(3*K);
            const symmTensor sd(dev(s));
            const scalar nd = std::sqrt(devEp && devEp);
            const scalar ns = std::sqrt(sd && sd);
            if (ns > 1e-6*sc)
            {
                eFlow = max(eFlow, maxMag(devEp/nd - sd/ns));
                eFlow = max(eFlow, mag(volEp/nd - std::sqrt(2.0)*dp.etaBar()));
            }
        }
        else if (r == DruckerPrager::apex)
        {
            eApex = max(eApex, maxMag(s - dp.apexStress()*I)/sc);
        }

        // Rotation invariance
        const tensor R(randomRotation(rnd));
        symmTensor sr(transform(R, trial));
        scalar epr = 0;
        dp.updateStress(symmTensor::zero, sr, epr);
        eRot = max(eRot, maxMag(sr - transform(R, s))/sc);
    }
    std::ostringstream os;
    os << " [elastic " << counts[0] << ", cone " << counts[1] << ", apex "
       << counts[2] << "]";
    check(ok && eAdm < tol, tag + " 1e4 random trials admissible, no NaN"
        + os.str(), eAdm, tol);
    check(eSurf < tol, tag + " cone returns on the cone (f = 0)", eSurf,
        tol);
    check(eApex == 0, tag + " apex returns exactly at xi c/eta", eApex, 0);
    check(eFlow < 1e-8, tag + " flow direction dev(s)/|s| and "
        "vol/dev = sqrt(2) etaBar", eFlow, 1e-8);
    check(eRot < tol, tag + " rotation invariance", eRot, tol);

    // Associated: closest point in the energy norm (variational inequality)
    if (psi == phi)
    {
        List<symmTensor> adm(300);
        forAll(adm, i)
        {
            adm[i] = randomSymm(rnd, S) - 0.5*S*I;
            scalar ep = 0;
            dp.updateStress(symmTensor::zero, adm[i], ep);
        }
        if (dp.eta() > 0) adm[0] = dp.apexStress()*I;
        scalar eVI = 0;
        for (label t = 0; t < 1000; ++t)
        {
            const symmTensor trial(randomSymm(rnd, S) - 0.3*S*I);
            symmTensor s(trial);
            scalar ep = 0;
            if (dp.update(symmTensor::zero, s, ep) == DruckerPrager::elastic)
            {
                continue;
            }
            const symmTensor dS(trial - s);
            const symmTensor eps((1 + dp.nu())*dS - (dp.nu()*tr(dS))*I);
            forAll(adm, i)
            {
                // Cosine in the energy norm
                const symmTensor d(adm[i] - s);
                const symmTensor epsD((1 + dp.nu())*d - (dp.nu()*tr(d))*I);
                if ((d && epsD) < 1e-16*(dS && eps)) continue;
                eVI = max(eVI, (eps && d)
                    /(std::sqrt((dS && eps)*(d && epsD)) + VSMALL));
            }
        }
        check(eVI < tol, tag + " closest point in the energy norm", eVI,
            tol);
    }

    if (c == 0 && dp.eta() > 0)
    {
        testDruckerPragerZero(dp, tag, psi, rnd);
    }
}


static void testDruckerPragerFits()
{
    const scalar c = 10e3, phi = 30;
    // A Mohr-Coulomb material for the edges
    const dictionary mcDict(makeDict(mcText(c, phi, phi)));
    autoPtr<constitutiveModel> mcModel = constitutiveModel::New("m", mcDict);
    const MohrCoulomb& mc = refCast<const MohrCoulomb>(mcModel());

    for (const word fit : {"outerCone", "innerCone"})
    {
        const dictionary dict(makeDict(dpText(c, phi, phi, fit)));
        autoPtr<constitutiveModel> model = constitutiveModel::New("d", dict);
        const DruckerPrager& dp = refCast<const DruckerPrager>(model());
        // Points of line 1 (s1 = s2) or line 2 (s2 = s3) below the apex
        const vector r =
            (fit == "outerCone")
          ? vector(1, 1, mc.k()) : vector(1, mc.k(), mc.k());
        scalar err = 0;
        for (const scalar t : {-1e3, -1e4, -1e5, -1e6})
        {
            const vector s(mc.apexStress()*vector::one + t*r);
            err = max(err, mag(dp.yieldFunction(diagonal(s)))/mag(t));
        }
        err = max(err, mag(dp.apexStress() - mc.apexStress())/mc.apexStress());
        check(err < 1e-12, "DP " + fit + " passes through the Mohr-Coulomb "
            + (fit == "outerCone" ? "compression" : "extension")
            + " edges and apex", err, 1e-12);
    }

    for (const scalar psi : {0.0, 15.0, 30.0})
    {
        const dictionary dict(makeDict(dpText(c, phi, psi, "planeStrain")));
        autoPtr<constitutiveModel> model = constitutiveModel::New("d", dict);
        const scalar err = planeStrainFailure(model(), c, phi, psi);
        check(err < 1e-10, "DP planeStrain (psi=" + num(psi)
            + ") steady plane-strain flow on the Mohr-Coulomb failure line",
            err, 1e-10);
    }
}


void testDruckerPrager()
{
    for (const word fit : {"outerCone", "innerCone", "planeStrain"})
    {
        testDruckerPragerSet(0, 30, 0, fit);
        testDruckerPragerSet(0, 30, 30, fit);
        testDruckerPragerSet(10e3, 45, 10, fit);
        testDruckerPragerSet(10e3, 45, 45, fit);
    }
    testDruckerPragerSet(50e3, 0, 0, "planeStrain");   // von Mises
    testDruckerPragerFits();
}


// ************************************************************************* //
