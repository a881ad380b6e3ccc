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

Application
    Test-constitutiveModels

Description
    Unit checks of the soil constitutive models (tension positive):
    - linearElastic: uniaxial strain, Hooke's law against the compliance,
      moduli and p-wave speed, the batch loop;
    - MohrCoulomb for several cohesion/friction/dilation sets, Tresca and
      a tension cut-off: elastic trial unchanged, the Clausen et al. regions
      (triaxial compression line, extension line, apex, plane), yield
      function zero to round-off after a return, admissibility, order,
      agreement of the region tests with a brute-force search over the
      active sets (Koiter's flow rule with non-negative multipliers),
      closest point in the energy norm for psi = phi, rotation invariance,
      exact zero stress at the origin apex, no NaN, plane-strain failure;
    - the packed MohrCoulomb update (four points per SIMD lane group):
      its polynomial acos, sin, cos against the library's, its result
      against the point-at-a-time update on generic, near-triaxial and
      near-hydrostatic trials, and the same result for a point whatever
      its position in the arrays;
    - DruckerPrager for the three fits: cone/apex, flow direction, closest
      point for psi = phi, rotation invariance, the fits touch the
      Mohr-Coulomb edges or reproduce its plane-strain failure;
    - bad input raises FatalIOError naming the keyword.
    Prints PASS:/FAIL: lines; exits 1 on any failure. TEST_DEBUG=1 in the
    environment prints the states behind some failures.

\*---------------------------------------------------------------------------*/

#include "constitutiveModelsTest.H"


// * * * * * * * * * * * * * * * * Bad input  * * * * * * * * * * * * * * * //

// The model of text must be refused with a message naming keyword
static void expectRefused
(
    const std::string& text,
    const std::string& keyword,
    const std::string& what
)
{
    unitTest::expectFatal
    (
        [&]()
        {
            const dictionary dict(makeDict(text));
            autoPtr<constitutiveModel> model =
                constitutiveModel::New("bad", dict);
        },
        keyword,
        what
    );
}

static void testBadInput()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const std::string mc = "MohrCoulombCoeffs { cohesion 0; frictionAngle 30;"
        " dilationAngle 0; }";
    expectRefused("model MohrCoulomb; rho 1669.5; E 75e6; nu 0.5; " + mc,
        "nu 0.5 is not allowed", "nu = 0.5");
    expectRefused("model linearElastic; rho 1669.5; E 75e6; nu -1;",
        "nu -1 is not allowed", "nu = -1");
    expectRefused("model linearElastic; rho 0; E 75e6; nu 0.3;",
        "rho 0 is not allowed", "rho = 0");
    expectRefused("model linearElastic; rho 1000; E -5; nu 0.3;",
        "E -5 is not allowed", "E < 0");
    expectRefused("model linearElastic; rho 1000; nu 0.3;", "E",
        "missing E");
    expectRefused(mcText(0, 90, 0), "frictionAngle 90 is not allowed",
        "frictionAngle = 90");
    expectRefused(mcText(0, -1, 0), "frictionAngle -1 is not allowed",
        "frictionAngle < 0");
    expectRefused(mcText(0, 45, 50), "dilationAngle 50 is not allowed",
        "dilationAngle > frictionAngle");
    expectRefused(mcText(-1, 30, 0), "cohesion -1 is not allowed",
        "cohesion < 0");
    expectRefused(mcText(1e3, 30, 0, "tensionCutoff -1;"),
        "tensionCutoff -1 is not allowed", "tensionCutoff < 0");
    expectRefused(dpText(0, 90, 0, "outerCone"),
        "frictionAngle 90 is not allowed", "DruckerPrager frictionAngle = 90");
    expectRefused(dpText(0, 30, 31, "outerCone"),
        "dilationAngle 31 is not allowed",
        "DruckerPrager dilationAngle > frictionAngle");
    expectRefused(dpText(0, 30, 0, "middleCone"), "middleCone",
        "DruckerPrager unknown fit");
    expectRefused("model CamClay; rho 1000; E 1e6; nu 0.3;", "CamClay",
        "unknown model");

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();

    // A cut-off above the apex is clipped (with a warning)
    const dictionary dict(makeDict(mcText(0, 30, 0, "tensionCutoff 1e3;")));
    autoPtr<constitutiveModel> model = constitutiveModel::New("sand", dict);
    const MohrCoulomb& m = refCast<const MohrCoulomb>(model());
    check(m.tensionCutoff() == 0, "tensionCutoff above the apex is clipped "
        "to c cot(phi)", m.tensionCutoff(), 0);
}


// * * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    testLinearElastic();
    testMohrCoulomb();
    testPackedMohrCoulomb();
    testDruckerPrager();
    testBadInput();

    // Reports
    {
        const dictionary dict(makeDict(mcText(0, 45, 0)));
        constitutiveModel::New("sand", dict)->report(Info);
        const dictionary dict2(makeDict(dpText(5e3, 30, 10, "planeStrain")));
        constitutiveModel::New("clay", dict2)->report(Info);
    }

    return finish();
}


// ************************************************************************* //