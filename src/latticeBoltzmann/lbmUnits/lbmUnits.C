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

\*---------------------------------------------------------------------------*/

#include "lbmUnits.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::lbmUnits::report(Ostream& os, const scalar Uref) const
{
    os  << "Lattice Boltzmann units" << nl
        << "    dx = " << dx_ << " m, dt = " << dt_ << " s, nu = " << nu_
        << " m2/s, rho = " << rho0_ << " kg/m3" << nl
        << "    tau = " << tau() << " (tau - 1/2 = " << tau() - 0.5 << ")"
        << ", lattice viscosity " << nuLattice() << nl
        << "    lattice sound speed " << soundSpeed() << " m/s (bulk modulus "
        << rho0_*sqr(soundSpeed()) << " Pa)" << nl
        << "    reference speed " << Uref << " m/s: lattice Mach "
        << Mach(Uref) << ", grid Reynolds number " << gridReynolds(Uref)
        << nl << endl;
}


// ************************************************************************* //
