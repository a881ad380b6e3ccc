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

#include "MRT.H"
#include "optionalEntry.H"
#include "addToRunTimeSelectionTable.H"
#include "DynamicList.H"

namespace Foam
{
namespace collisionModels
{
    defineTypeNameAndDebug(MRT, 0);
    addToRunTimeSelectionTable(collisionModel, MRT, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::collisionModels::MRT::buildBasis()
{
    const label Q = velocitySet_.Q();
    const List<labelVector>& c = velocitySet_.c();
    const scalarList& w = velocitySet_.w();

    auto dot = [&](const scalarList& a, const scalarList& b)
    {
        scalar s = 0;
        for (label q = 0; q < Q; ++q)
        {
            s += w[q]*a[q]*b[q];
        }
        return s;
    };

    // Monomials by degree; the trace c.c first among degree 2 so that the
    // bulk mode is one basis vector
    DynamicList<scalarList> basis;
    DynamicList<label> degree;
    DynamicList<bool> isTrace;

    auto tryAdd = [&](scalarList v, const label deg, const bool trace)
    {
        for (const scalarList& b : basis)
        {
            const scalar p = dot(v, b);
            for (label q = 0; q < Q; ++q)
            {
                v[q] -= p*b[q];
            }
        }
        const scalar n = std::sqrt(dot(v, v));
        if (n > 1e-8 && basis.size() < Q)
        {
            for (label q = 0; q < Q; ++q)
            {
                v[q] /= n;
            }
            basis.append(v);
            degree.append(deg);
            isTrace.append(trace);
        }
    };

    for (label deg = 0; deg <= 6; ++deg)
    {
        if (deg == 2)
        {
            scalarList v(Q);
            for (label q = 0; q < Q; ++q)
            {
                v[q] = scalar(c[q].x()*c[q].x() + c[q].y()*c[q].y() + c[q].z()*c[q].z());
            }
            tryAdd(v, 2, true);
        }
        for (label a = 0; a <= 2; ++a)
        {
            for (label b = 0; b <= 2; ++b)
            {
                for (label e = 0; e <= 2; ++e)
                {
                    if (a + b + e != deg)
                    {
                        continue;
                    }
                    scalarList v(Q);
                    for (label q = 0; q < Q; ++q)
                    {
                        v[q] = std::pow(scalar(c[q].x()), a)
                              *std::pow(scalar(c[q].y()), b)
                              *std::pow(scalar(c[q].z()), e);
                    }
                    tryAdd(v, deg, false);
                }
            }
        }
    }

    if (basis.size() != Q)
    {
        FatalErrorInFunction
            << "Could not build a moment basis of " << Q << " vectors"
            << abort(FatalError);
    }

    M_.setSize(Q*Q);
    forAll(basis, k)
    {
        for (label q = 0; q < Q; ++q)
        {
            M_[k*Q + q] = basis[k][q];
        }
    }
    degree_.transfer(degree);
    isTrace_.transfer(isTrace);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModels::MRT::MRT
(
    const dictionary& dict,
    const velocitySet& vs
)
:
    collisionModel(typeName, dict, vs),
    magic_(optionalEntry<scalar>(coeffs_, "magic", 3.0/16.0)),
    omegaEven_(optionalEntry<scalar>(coeffs_, "omegaEven", 1.0)),
    omegaBulk_(optionalEntry<scalar>(coeffs_, "omegaBulk", -1.0))
{
    if (!(magic_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "MRTCoeffs: magic " << magic_ << " is not allowed: it must"
            << " be > 0 (3/16 for exact half-way walls)" << exit(FatalIOError);
    }
    if (!(omegaEven_ > 0 && omegaEven_ < 2))
    {
        FatalIOErrorInFunction(dict)
            << "MRTCoeffs: omegaEven " << omegaEven_ << " is not allowed:"
            << " relaxation rates must lie in (0, 2)" << exit(FatalIOError);
    }
    if (omegaBulk_ != -1 && !(omegaBulk_ > 0 && omegaBulk_ < 2))
    {
        FatalIOErrorInFunction(dict)
            << "MRTCoeffs: omegaBulk " << omegaBulk_ << " is not allowed:"
            << " relaxation rates must lie in (0, 2)" << exit(FatalIOError);
    }
    buildBasis();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::collisionModels::MRT::streamCollide
(
    const lbmKernelArgs& a,
    lbmKernelStats& stats
) const
{
    const scalar omega = a.omega;
    const scalar omegaOdd = 1.0/(magic_/(1.0/omega - 0.5) + 0.5);
    const scalar sBulk = omegaBulk_ > 0 ? omegaBulk_ : 0;
    const scalar bulkFixed = omegaBulk_ > 0 ? 1 : 0;
    const scalar sEven = omegaEven_;
    dispatch<MRTOperator>
    (
        a, stats,
        [=](auto vs)
        {
            return MRTOperator<decltype(vs)>
            {
                sBulk, bulkFixed, omegaOdd, sEven
            };
        }
    );
}


void Foam::collisionModels::MRT::report(Ostream& os) const
{
    os  << "    collision model MRT (weighted-orthonormal Hermite basis),"
        << " magic " << magic_ << ", omegaEven " << omegaEven_
        << ", omegaBulk "
        << (omegaBulk_ > 0 ? Foam::name(omegaBulk_) : word("1/tau")) << nl;
}


// ************************************************************************* //
