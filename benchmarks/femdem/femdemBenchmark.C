/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Application
    femdemBenchmark

Description
    Throughput and memory of libfemdem on one core:
    - intact: a rectangle of >= 1e5 triangles (all joints intact) under
      compression, with and without the contact search;
    - fragmented: every joint broken, the triangles pressed together and
      shaken so that contact is active between most neighbours.
    Prints triangle-steps per CPU second and bytes per triangle (the state, the
    joint topology and the contact work space included) on '>>' lines, the
    rate of the median step (per-step thread CPU time: less scattered on a
    shared machine) and a hash of the final node positions' bits (two builds
    of libfemdem integrate bitwise the same trajectories if and only if, up
    to hash collisions, they print the same hashes).

Usage
    femdemBenchmark [nx ny steps nxFragmented nyFragmented stepsFragmented
        [cases [skin]]]
    cases: the letters of the cases to run, i intact, b blocky, f
    fragmented (default ibf; e.g. f for a profile of the fragmented case);
    skin: potentialCoeffs.skin (default: the contact law's)
    Where the CPU has AVX-512 (the triangle, joint and contact loops in
    lanes), the intact case without contact and the fragmented case also run
    with the scalar loops: the same hashes, their own rates.

\*---------------------------------------------------------------------------*/

#include "femdemSolid.H"
#include "contactLaw.H"
#include "potentialContact.H"
#include "IStringStream.H"
#include "Random.H"
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdint>
#include <algorithm>
#include <vector>
#include <time.h>
#include <string>

using namespace Foam;

namespace
{

//- Verlet skin of the potential contact (negative: its default)
scalar skin = -1;

dictionary props(const word& contact)
{
    const std::string coeffs = skin < 0 ? "" :
        "potentialCoeffs { skin " + std::to_string(skin) + "; }";
    IStringStream is
    (
        coeffs + "cohesiveLaw munjiza; contactLaw " + contact + ";"
        "materials { rock { E 19.5e9; nu 0.265; rho 2000;"
        " tensileStrength 3.5e6; cohesion 17.6e6; frictionAngle 23;"
        " GI 100; GII 1750; dampingRatio 0.1; } }"
        "boundaryConditions { bottom { type fixed; }"
        " top { type velocity; value (0 -0.5); } }"
    );
    return dictionary(is);
}


double threadSeconds()
{
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9*ts.tv_nsec;
}


double seconds(const std::chrono::steady_clock::time_point& t0)
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
}


void run
(
    const word& name,
    femdemSolid& solid,
    const label steps
)
{
    solid.step();   // warm-up (allocates the contact work space)
    const auto* pc =
        dynamic_cast<const contactLaws::potential*>(&solid.contact());
    const label builds0 = pc ? pc->nListBuilds() : 0;
    // CPU time of the process (one thread): the machine may be shared
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    // Each step's thread CPU time too: on a shared machine the median
    // step is far less scattered than the total (preemption, other jobs)
    std::vector<double> stepTimes(steps);
    for (label i = 0; i < steps; ++i)
    {
        const double s0 = threadSeconds();
        solid.step();
        stepTimes[i] = threadSeconds() - s0;
    }
    const double wall = seconds(t0);
    const double dt = double(std::clock() - c0)/CLOCKS_PER_SEC;
    const double rate = double(solid.nTriangles())*steps/dt;
    std::sort(stepTimes.begin(), stepTimes.end());
    const double median = steps ? stepTimes[steps/2] : 0;
    const double bytes = double(solid.memoryBytes())/solid.nTriangles();
    std::printf
    (
        ">> %s: %ld triangles, %ld joints (%ld broken), %ld steps in %.2f s"
        " CPU (%.2f s wall):"
        " %.3g triangle-steps/s/core, %.0f bytes/triangle,"
        " contact pairs: %ld candidates, %ld active\n",
        name.c_str(), long(solid.nTriangles()), long(solid.nJoints()),
        long(solid.nBrokenJoints()), long(steps), dt, wall, rate, bytes,
        long(solid.contact().nCandidatePairs()),
        long(solid.contact().nActivePairs())
    );
    std::printf
    (
        ">> %s: median step %.3g triangle-steps/s/core\n", name.c_str(),
        median > 0 ? solid.nTriangles()/median : 0.0
    );
    // Hash of the node positions' bits: two builds of the library give the
    // same hash only if they integrate bitwise the same trajectories
    std::uint64_t hash = 1469598103934665603ull;
    const unsigned char* raw =
        reinterpret_cast<const unsigned char*>(solid.x().cdata());
    const std::size_t nBytes = solid.x().size()*sizeof(vector2D);
    for (std::size_t i = 0; i < nBytes; ++i)
    {
        hash = (hash ^ raw[i])*1099511628211ull;
    }
    std::printf
    (
        ">> %s: position hash %016llx\n", name.c_str(),
        static_cast<unsigned long long>(hash)
    );
    if (pc)
    {
        std::printf
        (
            ">> %s: %ld candidate-list builds in %ld steps, %ld listed pairs\n",
            name.c_str(), long(pc->nListBuilds() - builds0), long(steps),
            long(pc->nListedPairs())
        );
    }
}

} // End anonymous namespace


std::string codeName(const label code)
{
    return
        code == femdemSolid::AVX512
      ? "x86-64-v4 (AVX-512), blocks of lanes"
      : "baseline x86-64, scalar loops";
}


int main(int argc, char *argv[])
{
    const label nx = argc > 1 ? atoi(argv[1]) : 250;
    const label ny = argc > 2 ? atoi(argv[2]) : 200;
    const label steps = argc > 3 ? atoi(argv[3]) : 200;
    const label fx = argc > 4 ? atoi(argv[4]) : 100;
    const label fy = argc > 5 ? atoi(argv[5]) : 100;
    const label fsteps = argc > 6 ? atoi(argv[6]) : 200;
    const std::string cases = argc > 7 ? argv[7] : "ibf";
    if (argc > 8) skin = atof(argv[8]);
    auto runs = [&cases](const char c)
    {
        return cases.find(c) != std::string::npos;
    };
    std::printf
    (
        ">> element, joint and contact loops: %s (the CPU's best: %s)\n",
        codeName(femdemSolid::vectorCode()).c_str(),
        codeName(femdemSolid::cpuVectorCode()).c_str()
    );

    // Intact: 0.5 x 0.4 m, compressed from the top
    if (runs('i'))
    {
        const triangleMesh mesh = triangleMesh::rectangle
        (
            vector2D(0, 0), vector2D(0.5, 0.4), nx, ny, "rock"
        );
        femdemSolid noContact(mesh, props("none"));
        run("intact, contactLaw none", noContact, steps);
        // The other codes on the same case: the same hash (bitwise the same
        // forces), their own rates
        const femdemSolid::vectorCodeType best = femdemSolid::vectorCode();
        for (label code = best - 1; code >= 0; --code)
        {
            femdemSolid::setVectorCode(femdemSolid::vectorCodeType(code));
            femdemSolid other(mesh, props("none"));
            run
            (
                "intact, contactLaw none, code " + codeName(code),
                other,
                steps
            );
        }
        femdemSolid::setVectorCode(best);
        femdemSolid solid(mesh, props("potential"));
        run("intact, contactLaw potential", solid, steps);
    }

    // Blocky: joints on every 4th grid line broken (fragments of 4 x 4
    // cells = 32 triangles), random block velocities, pressed
    if (runs('b'))
    {
        const triangleMesh mesh = triangleMesh::rectangle
        (
            vector2D(0, 0), vector2D(0.4, 0.4), 2*fx, 2*fy, "rock"
        );
        femdemSolid solid(mesh, props("potential"));
        const scalar h = 0.4/(2*fx);
        auto onLine = [h](const scalar c)
        {
            const scalar r = c/(4*h);
            return mag(r - std::round(r)) < 1e-6;
        };
        const List<vector2D> X(solid.x());
        forAll(solid.topology().jointNodes(), j)
        {
            const jointNodeList& n = solid.topology().jointNodes()[j];
            const vector2D& a = X[n[0]];
            const vector2D& b = X[n[1]];
            if
            (
                (onLine(a.x()) && onLine(b.x()) && mag(a.x() - b.x()) < 1e-12)
             || (onLine(a.y()) && onLine(b.y()) && mag(a.y() - b.y()) < 1e-12)
            )
            {
                solid.setBroken(j);
            }
        }
        Random rnd(4321);
        const femdemSolid::fragmentData fr = solid.fragments();
        List<vector2D> vFrag(fr.mass.size());
        for (vector2D& v : vFrag)
        {
            v = vector2D(rnd.sample01<scalar>() - 0.5, rnd.sample01<scalar>() - 0.5);
        }
        const labelList& fragOf = solid.view().fragmentOfTriangle();
        forAll(solid.v(), n) solid.vRef()[n] = vFrag[fragOf[n/3]];
        for (label i = 0; i < 50; ++i) solid.step();
        run
        (
            "blocky (" + Foam::name(fr.mass.size()) + " fragments of 32 triangles),"
            " contactLaw potential",
            solid,
            fsteps
        );
    }

    // Fragmented: all joints broken, random velocities, pressed; where the
    // CPU has AVX-512 also with the scalar code (the same hash)
    const femdemSolid::vectorCodeType best = femdemSolid::vectorCode();
    for (label code = best; code >= 0 && runs('f'); --code)
    {
        femdemSolid::setVectorCode(femdemSolid::vectorCodeType(code));
        const triangleMesh mesh = triangleMesh::rectangle
        (
            vector2D(0, 0), vector2D(0.2, 0.2), fx, fy, "rock"
        );
        femdemSolid solid(mesh, props("potential"));
        for (label j = 0; j < solid.nJoints(); ++j) solid.setBroken(j);
        Random rnd(1234);
        forAll(solid.v(), n)
        {
            solid.vRef()[n] =
                vector2D(rnd.sample01<scalar>() - 0.5, rnd.sample01<scalar>() - 0.5);
        }
        // Let the fragments come into contact
        for (label i = 0; i < 50; ++i) solid.step();
        run
        (
            code == best
          ? "fragmented, contactLaw potential"
          : "fragmented, contactLaw potential, code " + codeName(code),
            solid,
            fsteps
        );
    }
    femdemSolid::setVectorCode(best);
    return 0;
}


// ************************************************************************* //
