/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Application
    ductNetworkPartitionCheck

Description
    Test of ductNetwork::distribute / collect (ductPartition;
    tests/regression/ductNetworkPartition.sh): a network of narrow ducts
    (an nx x ny grid of control volumes, ducts along x or y and junction
    voids, joined to their grid neighbours and, every seventh, to a volume
    far away; mouths at the left edge from a high-pressure plenum of
    products and at the right edge into air at low pressure) whose walls
    breathe (each volume's size oscillates by +-amplitude), run on every
    rank twice: whole (the serial reference, the same on every rank) and
    distributed over the ranks, over the same steps, each step sub-cycled
    at the network's own stable step as crackNetwork::endStep does. After
    every step the distributed network is collected and compared with the
    whole one: content, primitives, wall work and mean pressure of every
    volume, the sub-steps and their sizes, and, on the rank of a mouth's
    volume, what entered through the mouth. Prints per rank the own and
    ghost volumes and the interfaces computed, per step the largest
    relative difference, and the last line 'max relative difference D,
    differing volumes N, differing mouths M, differing sub-steps K,
    sub-steps S, mass change through the mouths R' (relative).

    Options: -nx, -ny, -steps, -owner stripes|random|blocks,
    -materials one|two, -flux HLLC|KurganovTadmor, -RKorder 1|2|3,
    -friction f, -amplitude a, -kapila true|false.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "ductNetwork.H"
#include "IStringStream.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include <cstring>

using namespace Foam;

namespace
{

dictionary dictOf(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

//- A repeatable pseudo-random number in [0, 1) from an integer
scalar hashUnit(const label i, const label salt)
{
    typedef unsigned long long ull;
    ull h = 0x9E3779B97F4A7C15ull*static_cast<ull>(i + 1);
    h ^= 0xBF58476D1CE4E5B9ull*static_cast<ull>(salt + 7);
    h ^= h >> 31; h *= 0x94D049BB133111EBull; h ^= h >> 29;
    return static_cast<scalar>(h >> 11)/static_cast<scalar>(1ull << 53);
}

//- The grid network: geometry at size factor s(i) of the base volumes
struct gridNetwork
{
    label nx, ny;
    scalar w, dx;
    scalarField base;
    labelList owner, neighbour;
    vectorField Sf, axis;

    gridNetwork(const label nx_, const label ny_)
    :
        nx(nx_), ny(ny_), w(2e-4), dx(4e-3)
    {
        const label n = nx*ny;
        base.setSize(n);
        axis.setSize(n);
        for (label i = 0; i < n; ++i)
        {
            base[i] = w*dx*(0.5 + hashUnit(i, 1));
            const label kind = i % 5;
            axis[i] =
                kind == 4 ? vector::zero
              : kind % 2 ? vector(0, 1, 0) : vector(1, 0, 0);
        }
        DynamicList<label> o, nb;
        DynamicList<vector> s;
        for (label j = 0; j < ny; ++j)
        {
            for (label i = 0; i < nx; ++i)
            {
                const label c = j*nx + i;
                const scalar a = w*(0.3 + hashUnit(c, 2));
                if (i + 1 < nx)
                {
                    o.append(c); nb.append(c + 1); s.append(vector(a, 0, 0));
                }
                if (j + 1 < ny)
                {
                    o.append(c); nb.append(c + nx); s.append(vector(0, a, 0));
                }
                if (c % 7 == 3)
                {
                    const label far = (c*13 + 5) % n;
                    if (far != c)
                    {
                        o.append(c); nb.append(far);
                        s.append(vector(0.5*a, 0.5*a, 0));
                    }
                }
            }
        }
        // Mouths: left edge in, right edge out
        for (label j = 0; j < ny; ++j)
        {
            o.append(j*nx); nb.append(-1); s.append(vector(-w, 0, 0));
            o.append(j*nx + nx - 1); nb.append(-1); s.append(vector(w, 0, 0));
        }
        owner.transfer(o);
        neighbour.transfer(nb);
        Sf.transfer(s);
    }

    label size() const { return base.size(); }

    scalar volume(const label i, const scalar t, const scalar amp) const
    {
        const scalar phase = 6.283185307179586*hashUnit(i, 3);
        return base[i]*(1 + amp*std::sin(phase + 2e5*t));
    }

    void setGeometry(ductNetwork& net) const
    {
        ductNetwork::geometry& g = net.geom();
        forAll(base, i)
        {
            g.axis[i] = axis[i];
            g.wallArea[i] = 2*dx;
        }
        g.owner = owner;
        g.neighbour = neighbour;
        g.Sf = Sf;
    }

    void setPlenums(ductNetwork& net, const bool two) const
    {
        ductNetwork::plenumStates& pl = net.plenum();
        forAll(owner, f)
        {
            if (neighbour[f] >= 0) continue;
            const bool in = (owner[f] % nx) == 0;
            pl.p[f] = in ? 1e8 : 1e5;
            pl.rho[f] = in ? 300 : 1.2;
            pl.alpha1[f] = two ? (in ? 1 : 0) : 1;
            pl.rho1[f] = in ? 300 : 1.2;
            pl.rho2[f] = in ? 300 : 1.2;
            pl.maxMass[f] = in && (owner[f]/nx) % 2 ? 2e-6 : 0;
        }
    }
};


labelList volumeRanks(const gridNetwork& grid, const word& how)
{
    const label nProcs = Pstream::nProcs();
    labelList rank(grid.size());
    forAll(rank, c)
    {
        const label i = c % grid.nx, j = c/grid.nx;
        if (how == "stripes")
        {
            rank[c] = min(nProcs - 1, i*nProcs/grid.nx);
        }
        else if (how == "blocks")
        {
            rank[c] = ((i/3) + (j/3)) % nProcs;
        }
        else
        {
            rank[c] = label(hashUnit(c, 4)*nProcs) % nProcs;
        }
    }
    return rank;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noBanner();
    argList::noCheckProcessorDirectories();
    argList::addOption("nx", "label", "volumes along x (default 24)");
    argList::addOption("ny", "label", "volumes along y (default 10)");
    argList::addOption("steps", "label", "steps (default 40)");
    argList::addOption("owner", "word", "stripes|random|blocks");
    argList::addOption("materials", "word", "one|two (default two)");
    argList::addOption("flux", "word", "HLLC|KurganovTadmor");
    argList::addOption("RKorder", "label", "1|2|3 (default 2)");
    argList::addOption("friction", "scalar", "Fanning factor (default 0)");
    argList::addOption("amplitude", "scalar", "wall breathing (default 0.3)");
    argList::addOption("kapila", "word", "true|false (default true)");
    argList args(argc, argv, false, false);

    const label nx = args.getOrDefault<label>("nx", 24);
    const label ny = args.getOrDefault<label>("ny", 10);
    const label nSteps = args.getOrDefault<label>("steps", 40);
    const word how = args.getOrDefault<word>("owner", "stripes");
    const bool two = args.getOrDefault<word>("materials", "two") == "two";
    const scalar amp = args.getOrDefault<scalar>("amplitude", 0.3);

    const std::string mixtureText =
        two
      ? "materials (products air);"
        "products { equationOfState JWL; explosive TNT; }"
        "air { equationOfState idealGas; gamma 1.4; }"
      : "materials (air); air { equationOfState idealGas; gamma 1.4; }";
    blastMixture mix(dictOf(mixtureText));
    const std::string netText =
        "flux " + args.getOrDefault<word>("flux", "HLLC")
      + "; RKorder " + std::to_string(args.getOrDefault<label>("RKorder", 2))
      + "; frictionFactor "
      + std::to_string(args.getOrDefault<scalar>("friction", 0))
      + "; kapilaTerm " + args.getOrDefault<word>("kapila", "true") + ";";

    const gridNetwork grid(nx, ny);
    const label n = grid.size(), nf = grid.owner.size();
    ductNetwork whole(mix, dictOf(netText)), dist(mix, dictOf(netText));
    for (ductNetwork* net : {&whole, &dist})
    {
        net->setSize(n, nf);
        grid.setGeometry(*net);
        forAll(grid.base, i)
        {
            net->geom().V0[i] = grid.volume(i, 0, amp);
        }
        grid.setPlenums(*net, two);
        for (label i = 0; i < n; ++i)
        {
            // Products at high pressure in the left third, air elsewhere
            const bool hot = (i % nx) < nx/3;
            const scalar p = hot ? 2e7*(0.5 + hashUnit(i, 5)) : 1e5;
            const scalar rho = hot ? 100*(0.5 + hashUnit(i, 6)) : 1.2;
            net->setState(i, rho, Zero, p, two ? (hot ? 1 : 0) : 1);
        }
    }
    const labelList rank(volumeRanks(grid, how));
    const scalar mass0 = whole.mass();

    const scalar dtStep = 1e-6;
    scalar maxRel = 0, t = 0;
    label nDiffVol = 0, nDiffMouth = 0, nSub = 0, nSubDiff = 0;
    bool first = true;
    for (label step = 0; step < nSteps; ++step)
    {
        dist.distribute(rank);
        if (first)
        {
            first = false;
            const ductPartition& part = dist.partition();
            Pout<< "rank " << Pstream::myProcNo() << ": own volumes "
                << part.own().size() << " of " << n << ", ghosts "
                << part.ghosts().size() << ", interfaces computed "
                << part.faces().size() << " of " << nf << endl;
        }
        scalarField mouthIn(nf, 0), mouthInDist(nf, 0);
        scalar s = 0;
        while (s < dtStep*(1 - 1e-12))
        {
            // The volumes move linearly over each sub-step, as in endStep
            for (ductNetwork* net : {&whole, &dist})
            {
                forAll(grid.base, i)
                {
                    net->geom().V0[i] = grid.volume(i, t + s, amp);
                    net->geom().V1[i] = grid.volume(i, t + dtStep, amp);
                }
            }
            const scalar hW = min(dtStep - s, whole.maxDeltaT(0.4));
            const scalar hD = min(dtStep - s, dist.maxDeltaT(0.4));
            if (hW != hD) ++nSubDiff;
            for (ductNetwork* net : {&whole, &dist})
            {
                forAll(grid.base, i)
                {
                    net->geom().V1[i] = grid.volume(i, t + s + hW, amp);
                }
                net->advance(hW);
            }
            forAll(grid.owner, f)
            {
                if (grid.neighbour[f] >= 0) continue;
                mouthIn[f] += whole.inMass()[f] + whole.inEnergy()[f];
                mouthInDist[f] += dist.inMass()[f] + dist.inEnergy()[f];
            }
            s += hW;
            ++nSub;
        }
        t += dtStep;
        forAll(grid.owner, f)
        {
            if (grid.neighbour[f] < 0 && rank[grid.owner[f]] == Pstream::myProcNo())
            {
                if (mouthIn[f] != mouthInDist[f]) ++nDiffMouth;
            }
        }
        dist.collect();

        scalar rel = 0;
        label nDiff = 0;
        for (label i = 0; i < n; ++i)
        {
            const ductNetwork::content a = whole.contentOf(i);
            const ductNetwork::content b = dist.contentOf(i);
            const scalar va[] =
            {
                a.m, a.mE, a.aV, a.m1, a.mU.x(), a.mU.y(), whole.p()[i],
                whole.rho()[i], whole.c()[i], whole.alpha1()[i],
                whole.wallWorkOf()[i], whole.meanPressure()[i]
            };
            const scalar vb[] =
            {
                b.m, b.mE, b.aV, b.m1, b.mU.x(), b.mU.y(), dist.p()[i],
                dist.rho()[i], dist.c()[i], dist.alpha1()[i],
                dist.wallWorkOf()[i], dist.meanPressure()[i]
            };
            bool differs = false;
            for (unsigned k = 0; k < sizeof(va)/sizeof(va[0]); ++k)
            {
                if (va[k] != vb[k])
                {
                    differs = true;
                    rel = max(rel, mag(va[k] - vb[k])/max(mag(va[k]), VSMALL));
                }
            }
            if (differs) ++nDiff;
        }
        reduce(rel, maxOp<scalar>());
        reduce(nDiff, maxOp<label>());
        maxRel = max(maxRel, rel);
        nDiffVol = max(nDiffVol, nDiff);
        Info<< "step " << step + 1 << ": sub-steps " << nSub
            << ", max relative difference " << rel << ", differing volumes "
            << nDiff << endl;
    }
    reduce(nDiffMouth, sumOp<label>());
    reduce(nSubDiff, maxOp<label>());

    // The mouths worked: the network's mass changed through them
    Info<< "max relative difference " << maxRel << ", differing volumes "
        << nDiffVol << ", differing mouths " << nDiffMouth
        << ", differing sub-steps " << nSubDiff << ", sub-steps " << nSub
        << ", mass change through the mouths "
        << (whole.mass() - mass0)/mass0 << endl;
    return 0;
}
