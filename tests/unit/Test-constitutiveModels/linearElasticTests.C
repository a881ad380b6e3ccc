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
    Test-constitutiveModels: linearElastic (uniaxial strain, Hooke's law
    against the compliance, moduli and p-wave speed, the batch loop).

\*---------------------------------------------------------------------------*/

#include "constitutiveModelsTest.H"

// * * * * * * * * * * * * * * * linearElastic  * * * * * * * * * * * * * * //

void testLinearElastic()
{
    const dictionary dict(makeDict("model linearElastic; " + elasticPart()));
    autoPtr<constitutiveModel> model = constitutiveModel::New("soil", dict);
    const constitutiveModel& m = model();

    check(m.type() == "linearElastic", "linearElastic selected", 0, 0);

    const scalar E = 75e6, nu = 0.3;
    const scalar Mexact = E*(1 - nu)/((1 + nu)*(1 - 2*nu));
    const scalar lambdaExact = E*nu/((1 + nu)*(1 - 2*nu));
    scalar err =
        max
        (
            max
            (
                mag(m.M() - Mexact)/Mexact,
                mag(m.lambda() + 2*m.G() - Mexact)/Mexact
            ),
            max
            (
                mag(m.K() - (m.lambda() + 2*m.G()/3))/m.K(),
                mag(m.pWaveSpeed() - std::sqrt(Mexact/1669.5))
               /m.pWaveSpeed()
            )
        );
    check(err < 1e-14, "linearElastic moduli G, K, M and sqrt(M/rho)", err,
        1e-14);

    // Uniaxial strain along z
    const scalar eps = -1e-3;
    symmTensor sigma(Zero);
    scalar ep = 0.25;
    m.updateStress(symmTensor(0, 0, 0, 0, 0, eps), sigma, ep);
    err =
        max
        (
            mag(sigma.zz() - Mexact*eps),
            max
            (
                max(mag(sigma.xx() - lambdaExact*eps),
                    mag(sigma.yy() - lambdaExact*eps)),
                max(mag(sigma.xy()), max(mag(sigma.xz()), mag(sigma.yz())))
            )
        )/(Mexact*mag(eps));
    check(err < 1e-14 && ep == 0.25,
        "linearElastic uniaxial strain: sigma_zz = M eps, sigma_xx = "
        "sigma_yy = lambda eps", err, 1e-14);

    // Hooke's law on random increments, checked through the compliance
    Random rnd(1);
    err = 0;
    List<symmTensor> dEps(100), s0(100), s1(100);
    scalarList eps0(100, 0.0);
    forAll(dEps, i)
    {
        dEps[i] = randomSymm(rnd, 1e-3);
        s0[i] = randomSymm(rnd, 1e5);
        symmTensor s(s0[i]);
        scalar e = 0;
        m.updateStress(dEps[i], s, e);
        const symmTensor dS(s - s0[i]);
        const symmTensor back(((1 + nu)*dS - (nu*tr(dS))*I)/E);
        err = max(err, maxMag(back - dEps[i])/maxMag(dEps[i]));
        s1[i] = s;
    }
    check(err < 1e-12, "linearElastic Hooke exact (compliance inverts it)",
        err, 1e-12);

    // Batch loop equals the point loop
    List<symmTensor> sb(s0);
    m.updateStresses(sb.size(), dEps.cdata(), sb.data(), eps0.data());
    err = 0;
    forAll(sb, i)
    {
        err = max(err, maxMag(sb[i] - s1[i]));
    }
    check(err == 0, "linearElastic updateStresses equals updateStress", err,
        0);
}


// ************************************************************************* //
