// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    Test-particleStatistics

Description
    The computations of the particle-phase function objects on hand-built
    values with expected results worked out by hand:

    binnedDistribution: 7 values with weights over 4 bins of [0, 1), one
    on a bin edge (the bin above), one below, one at the upper end
    (above); the weights, fractions, PDF, mean, standard deviation,
    extremes. A narrow spread far from zero (1000 +- 0.001): its standard
    deviation to 1e-9. With -parallel the values are shared out over the
    processors and the results must be the same.

    solidsFlux::slabSums: 6 particles about a slab [0.375, 0.625) (binary
    exact), one on its lower face (in), one on its upper face (out), one
    beyond the axis range (the end bin): the bin sums, the upward and
    downward sums and the count.
*/

#include "argList.H"
#include "unitCheck.H"
#include "binnedDistribution.H"
#include "solidsFlux.H"
#include "IOstreams.H"
#include "Pstream.H"

using namespace Foam;
using unitTest::check;

int main(int argc, char *argv[])
{
    argList::noCheckProcessorDirectories();
    #include "setRootCase.H"

    const label me = Pstream::myProcNo();
    const label nProcs = Pstream::nProcs();

    // binnedDistribution ------------------------------------------------
    {
        const scalar x[] = {0.1, 0.3, 0.55, 0.99, -0.2, 1.0, 0.25};
        const scalar w[] = {1, 2, 1, 3, 1, 1, 1};
        binnedDistribution d(0, 1, 4);
        for (label i = 0; i < 7; ++i)
        {
            if (i % nProcs == me) d.add(x[i], w[i]);
        }
        d.reduce();
        for (label i = 0; i < 7; ++i)
        {
            if (i % nProcs == me) d.addSpread(x[i], w[i]);
        }
        d.reduceSpread();

        // Bins [0, .25) [.25, .5) [.5, .75) [.75, 1): 0.1 | 0.3, 0.25 |
        // 0.55 | 0.99; below: -0.2; above: 1.0; all the weight 10
        check("bin 0 weight", d.weights()[0], 1, 0);
        check("bin 1 weight (0.3 and the edge value 0.25)", d.weights()[1], 3, 0);
        check("bin 2 weight", d.weights()[2], 1, 0);
        check("bin 3 weight", d.weights()[3], 3, 0);
        check("below", d.below(), 1, 0);
        check("above (the upper end 1.0)", d.above(), 1, 0);
        check("total weight", d.total(), 10, 0);
        // mean = (0.1 + 0.6 + 0.55 + 2.97 - 0.2 + 1.0 + 0.25)/10 = 0.527
        check("mean", d.mean(), 0.527, 1e-14);
        // variance = sum w (x - 0.527)^2/10
        //  = (0.182329 + 2(0.051529) + 0.000529 + 3(0.214369)
        //     + 0.528529 + 0.223729 + 0.076729)/10 = 0.175801
        check("standard deviation", d.stdDev(), ::sqrt(0.175801), 1e-12);
        check("min", d.min(), -0.2, 0);
        check("max", d.max(), 1.0, 0);
        check("bin width", d.binWidth(), 0.25, 0);

        // The table: fractions and PDF of bin 1: 3/10 and 3/(10 0.25)
        OStringStream os;
        d.write(os, "x", "m");
        const string table(os.str());
        check("table: bin 1 row (0.25 0.5 0.375 3 0.3 1.2)",
            scalar(table.find("0.25\t0.5\t0.375\t3\t0.3\t1.2") != string::npos), 1, 0);
        check("table: below and above in the header",
            scalar(table.find("below 1, above 1") != string::npos), 1, 0);

        // A narrow spread far from zero: 1000 -+ 0.001, equal weights
        binnedDistribution n(900, 1100, 10);
        const scalar y[] = {999.999, 1000.001, 999.999, 1000.001};
        for (label i = 0; i < 4; ++i) if (i % nProcs == me) n.add(y[i], 1);
        n.reduce();
        for (label i = 0; i < 4; ++i) if (i % nProcs == me) n.addSpread(y[i], 1);
        n.reduceSpread();
        check("narrow spread: mean", n.mean(), 1000, 1e-15);
        check("narrow spread: standard deviation 0.001", n.stdDev(), 0.001, 1e-9);
    }

    // solidsFlux::slabSums ------------------------------------------------
    {
        // Slab: height 0.5, thickness 0.25 -> [0.375, 0.625); axis x over
        // [0, 1) in 2 bins
        const vector pos[] =
        {
            {0.2, 0, 0.45},     // in, bin 0, q = 1 x 2 = +2
            {0.7, 0, 0.55},     // in, bin 1, q = 3 x (-1) = -3
            {0.7, 0, 0.625},    // on the upper face: out
            {0.3, 0, 0.375},    // on the lower face: in, bin 0, q = 2 x 1 = +2
            {1.2, 0, 0.5},      // in, beyond the axis: end bin 1, q = +1
            {0.5, 0, 0.9}       // out
        };
        const vector vel[] =
        {
            {0, 0, 2}, {1, 0, -1}, {0, 0, 5}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}
        };
        const scalar vol[] = {1, 3, 1, 2, 1, 1};
        scalarField binSum(2, Zero);
        scalar upSum = 0, downSum = 0;
        const label inSlab = functionObjects::solidsFlux::slabSums
        (
            UList<vector>(const_cast<vector*>(pos), 6),
            UList<vector>(const_cast<vector*>(vel), 6),
            UList<scalar>(const_cast<scalar*>(vol), 6),
            vector(0, 0, 1), 0.5, 0.25, vector(1, 0, 0), 0, 1,
            binSum, upSum, downSum
        );
        check("slab: particles in it", inSlab, 4, 0);
        check("slab: bin 0 sum (2 + 2)", binSum[0], 4, 0);
        check("slab: bin 1 sum (-3 + 1)", binSum[1], -2, 0);
        check("slab: upward sum", upSum, 5, 0);
        check("slab: downward sum", downSum, -3, 0);
    }

    const label nFailed = returnReduce(unitTest::nFailed(), sumOp<label>());
    Info<< nl << (nFailed ? "FAILED: " : "passed: ") << nFailed
        << " failed check(s)" << endl;
    return nFailed ? 1 : 0;
}
