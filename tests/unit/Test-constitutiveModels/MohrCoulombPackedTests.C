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
    Test-constitutiveModels: the packed MohrCoulomb update (four points per
    SIMD lane group): its polynomial acos, sin, cos against the library's,
    its result against the point-at-a-time update, and the same result
    for a point whatever its position in the arrays.

\*---------------------------------------------------------------------------*/

#include "constitutiveModelsTest.H"

// * * * * * * * * * * * * * Packed Mohr-Coulomb * * * * * * * * * * * * * //

// The polynomial arc cosine, sine and cosine of the packed update against
// the library's
static void testPackedFunctions()
{
    using namespace packed;

    scalar errAcos = 0, errSin = 0, errCos = 0;
    const label n = 200000;
    for (label i = 0; i <= n; i += 4)
    {
        double4 x, a;
        for (int j = 0; j < 4; ++j)
        {
            x[j] = -1 + 2*scalar(min(i + j, n))/n;
            a[j] = (scalar(min(i + j, n))/n)*constant::mathematical::pi/3;
        }
        const double4 ac = packed::acos(x);
        double4 sn, cs;
        packed::sincos(a, sn, cs);
        for (int j = 0; j < 4; ++j)
        {
            errAcos = max(errAcos, mag(ac[j] - std::acos(x[j])));
            errSin = max(errSin, mag(sn[j] - std::sin(a[j])));
            errCos = max(errCos, mag(cs[j] - std::cos(a[j])));
        }
    }
    check(errAcos <= 2e-15, "packed acos against std::acos on [-1, 1]",
        errAcos, 2e-15);
    check(errSin <= 5e-16, "packed sin against std::sin on [0, pi/3]",
        errSin, 5e-16);
    check(errCos <= 5e-16, "packed cos against std::cos on [0, pi/3]",
        errCos, 5e-16);
}


// The packed update (four points per SIMD lane group, polynomial arc cosine,
// sine and cosine) against the point-at-a-time update with the library's
// functions, and the independence of a point's result from its place in
// the arrays
void testPackedMohrCoulomb()
{
    using namespace packed;

    testPackedFunctions();

    const List<std::pair<std::string, std::string>> sets
    ({
        {"c 0, phi 45, psi 0", mcText(0, 45, 0)},
        {"c 10 kPa, phi 30, psi 30", mcText(10e3, 30, 30)},
        {"c 10 kPa, phi 45, psi 10", mcText(10e3, 45, 10)},
        {"Tresca c 50 kPa", mcText(50e3, 0, 0)},
        {"c 20 kPa, phi 30, psi 10, cut-off 5 kPa",
            mcText(20e3, 30, 10, "tensionCutoff 5e3;")}
    });

    for (const auto& set : sets)
    {
        const dictionary dict(makeDict(set.second));
        const MohrCoulomb mc("sand", dict);
        const scalar S = 1e5;
        const scalar G = mc.G();
        Random rnd(1234);

        // Trial states: generic, near a triaxial line (two principal
        // values within 1e-9 .. 1e-4 of the scale, the third apart), near
        // the hydrostatic axis, and at rest in compression
        const label nTrial = 8000;
        List<symmTensor> s0(nTrial), dEps(nTrial);
        for (label i = 0; i < nTrial; ++i)
        {
            const label kind = i % 4;
            dEps[i] = randomSymm(rnd, (kind == 3 ? 1e-3 : 1)*S/G);
            if (kind == 0)
            {
                s0[i] = randomSymm(rnd, S) - 0.5*S*symmTensor::I;
                continue;
            }
            vector pv(randomPrincipal(rnd, S, -S, 0.1*S));
            if (kind == 1)
            {
                const scalar rel = std::pow(10.0, -9 + 5*rnd.sample01<scalar>());
                if (rnd.sample01<scalar>() < 0.5)
                {
                    pv.y() = pv.x() - rel*S;
                }
                else
                {
                    pv.y() = pv.z() + rel*S;
                }
                dEps[i] = Zero;
            }
            else if (kind == 2)
            {
                const scalar m = pv.x();
                pv = vector(m + 1e-7*S, m, m - 1e-7*S);
                dEps[i] = Zero;
            }
            const tensor R(randomRotation(rnd));
            s0[i] = symm(R & tensor(diagonal(pv)) & R.T());
        }

        scalar errStress = 0, errPlastic = 0;
        label regionMismatch = 0;
        List<symmTensor> sPacked(s0);
        scalarList epPacked(nTrial, 0.01);
        for (label i = 0; i < nTrial; ++i)
        {
            symmTensor sRef(s0[i]);
            scalar epRef = 0.01;
            const MohrCoulomb::returnRegion rRef =
                mc.updateScalar(dEps[i], sRef, epRef);
            symmTensor sOne(s0[i]);
            scalar epOne = 0.01;
            const MohrCoulomb::returnRegion rOne =
                mc.update(dEps[i], sOne, epOne);
            const scalar scale = maxMag(sRef) + mc.sigmaC() + S*1e-3;
            errStress = max(errStress, maxMag(sOne - sRef)/scale);
            errPlastic =
                max(errPlastic, mag(epOne - epRef)/(scale/G));
            if (rOne != rRef)
            {
                ++regionMismatch;
                if (std::getenv("TEST_DEBUG"))
                {
                    Info<< "    region " << label(rOne) << " vs "
                        << label(rRef) << " for " << s0[i] << " + "
                        << dEps[i] << nl;
                }
            }
        }
        check(errStress <= 1e-10,
            "MohrCoulomb " + set.first
          + ": packed update equals the point-at-a-time update (stress,"
            " relative)", errStress, 1e-10);
        check(errPlastic <= 1e-10,
            "MohrCoulomb " + set.first
          + ": packed update equals the point-at-a-time update (plastic"
            " strain, relative)", errPlastic, 1e-10);
        check(regionMismatch == 0,
            "MohrCoulomb " + set.first
          + ": packed update returns to the same region", regionMismatch, 0);

        // Arrays of 8000 and 7999 points against one point at a time:
        // bit for bit whatever the position in a group of four
        scalar errOrder = 0;
        for (const label n : {nTrial, nTrial - 1})
        {
            List<symmTensor> sArr(SubList<symmTensor>(s0, n, nTrial - n));
            scalarList epArr(n, 0.01);
            mc.updateStresses
            (
                n, dEps.cdata() + nTrial - n, sArr.data(), epArr.data()
            );
            for (label i = 0; i < n; ++i)
            {
                const label k = i + nTrial - n;
                symmTensor sOne(s0[k]);
                scalar epOne = 0.01;
                mc.update(dEps[k], sOne, epOne);
                errOrder = max(errOrder, maxMag(sArr[i] - sOne));
                errOrder = max(errOrder, mag(epArr[i] - epOne));
            }
        }
        check(errOrder == 0,
            "MohrCoulomb " + set.first
          + ": updateStresses gives every point the result of update"
            " (bit for bit, shifted arrays)", errOrder, 0);
    }
}


// ************************************************************************* //
