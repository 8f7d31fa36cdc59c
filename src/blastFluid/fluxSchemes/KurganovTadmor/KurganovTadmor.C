/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "KurganovTadmor.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace fluxSchemes
{
    defineTypeNameAndDebug(KurganovTadmor, 0);
    addToRunTimeSelectionTable(fluxScheme, KurganovTadmor, dictionary);
    defineTypeNameAndDebug(Kurganov, 0);
    addToRunTimeSelectionTable(fluxScheme, Kurganov, dictionary);
}
}


void Foam::fluxSchemes::KurganovTadmor::fluxes
(
    const label start,
    const label end,
    const vectorField& Sf,
    const scalarField& magSf,
    const blastFaceStates& s,
    const label nTracked,
    blastFaceFluxes& F
) const
{
    for (label f = start; f < end; ++f)
    {
        const scalar A = magSf[f];
        const vector n = Sf[f]/A;

        const scalar rhoL = s.rhoL[f], rhoR = s.rhoR[f];
        const vector& UL = s.UL[f];
        const vector& UR = s.UR[f];
        const scalar pL = s.pL[f], pR = s.pR[f];
        const scalar EL = s.EL[f], ER = s.ER[f];
        const scalar unL = UL & n, unR = UR & n;

        scalar ap = max(max(unL + s.cL[f], unR + s.cR[f]), scalar(0));
        scalar am = min(min(unL - s.cL[f], unR - s.cR[f]), scalar(0));
        if (symmetric_)
        {
            ap = max(ap, -am);
            am = -ap;
        }
        const scalar den = max(ap - am, VSMALL);
        const scalar wL = ap/den, wR = -am/den, wD = ap*am/den;

        F.rho[f] = A*(wL*rhoL*unL + wR*rhoR*unR + wD*(rhoR - rhoL));
        F.rhoU[f] =
            A
           *(
                wL*(rhoL*unL*UL + pL*n) + wR*(rhoR*unR*UR + pR*n)
              + wD*(rhoR*UR - rhoL*UL)
            );
        F.rhoE[f] =
            A*(wL*(EL + pL)*unL + wR*(ER + pR)*unR + wD*(ER - EL));
        F.uS[f] = A*(wL*unL + wR*unR);

        if (nTracked > 0)
        {
            const scalar r1L = rhoL*s.Y1L[f], r1R = rhoR*s.Y1R[f];
            F.rhoY1[f] = A*(wL*r1L*unL + wR*r1R*unR + wD*(r1R - r1L));
            const scalar aL = s.alphaL[f], aR = s.alphaR[f];
            F.alpha[f] = A*(wL*aL*unL + wR*aR*unR + wD*(aR - aL));
            if (nTracked > 1)
            {
                const scalar r2L = rhoL*s.Y2L[f], r2R = rhoR*s.Y2R[f];
                F.rhoY2[f] = A*(wL*r2L*unL + wR*r2R*unR + wD*(r2R - r2L));
                const scalar bL = s.alpha2L[f], bR = s.alpha2R[f];
                F.alpha2[f] = A*(wL*bL*unL + wR*bR*unR + wD*(bR - bL));
            }
        }
    }
}


// ************************************************************************* //
