/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "HLLC.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace fluxSchemes
{
    defineTypeNameAndDebug(HLLC, 0);
    addToRunTimeSelectionTable(fluxScheme, HLLC, dictionary);
}
}


void Foam::fluxSchemes::HLLC::fluxes
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

        const scalar SL = min(unL - s.cL[f], unR - s.cR[f]);
        const scalar SR = max(unL + s.cL[f], unR + s.cR[f]);

        const scalar mL = rhoL*(SL - unL);
        const scalar mR = rhoR*(SR - unR);
        const scalar Sstar = (pR - pL + mL*unL - mR*unR)/(mL - mR);

        scalar Frho, FE, uf;
        vector FU;

        if (SL >= 0)
        {
            Frho = rhoL*unL;
            FU = Frho*UL + pL*n;
            FE = (EL + pL)*unL;
            uf = unL;
        }
        else if (SR <= 0)
        {
            Frho = rhoR*unR;
            FU = Frho*UR + pR*n;
            FE = (ER + pR)*unR;
            uf = unR;
        }
        else if (Sstar >= 0)
        {
            // F*_L = F_L + S_L (U*_L - U_L)
            const scalar chi = (SL - unL)/(SL - Sstar);
            const scalar rhoS = rhoL*chi;
            const vector UstarL = UL + (Sstar - unL)*n;
            const scalar EstarL =
                chi*(EL + (Sstar - unL)*(rhoL*Sstar + pL/(SL - unL)));
            Frho = rhoL*unL + SL*(rhoS - rhoL);
            FU = rhoL*unL*UL + pL*n + SL*(rhoS*UstarL - rhoL*UL);
            FE = (EL + pL)*unL + SL*(EstarL - EL);
            uf = unL + SL*(chi - 1);
        }
        else
        {
            const scalar chi = (SR - unR)/(SR - Sstar);
            const scalar rhoS = rhoR*chi;
            const vector UstarR = UR + (Sstar - unR)*n;
            const scalar EstarR =
                chi*(ER + (Sstar - unR)*(rhoR*Sstar + pR/(SR - unR)));
            Frho = rhoR*unR + SR*(rhoS - rhoR);
            FU = rhoR*unR*UR + pR*n + SR*(rhoS*UstarR - rhoR*UR);
            FE = (ER + pR)*unR + SR*(EstarR - ER);
            uf = unR + SR*(chi - 1);
        }

        F.rho[f] = A*Frho;
        F.rhoU[f] = A*FU;
        F.rhoE[f] = A*FE;
        F.uS[f] = A*uf;

        if (nTracked > 0)
        {
            const bool leftUpwind = (Sstar >= 0);
            F.rhoY1[f] = F.rho[f]*(leftUpwind ? s.Y1L[f] : s.Y1R[f]);
            F.alpha[f] = F.uS[f]*(leftUpwind ? s.alphaL[f] : s.alphaR[f]);
            if (nTracked > 1)
            {
                F.rhoY2[f] = F.rho[f]*(leftUpwind ? s.Y2L[f] : s.Y2R[f]);
                F.alpha2[f] =
                    F.uS[f]*(leftUpwind ? s.alpha2L[f] : s.alpha2R[f]);
            }
        }
    }
}


// ************************************************************************* //
