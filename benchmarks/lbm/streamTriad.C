//------------------------------------------------------------------------------
//   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
//------------------------------------------------------------------------------
// Program
//     streamTriad
//
// Description
//     STREAM-style triad a[i] = b[i] + s c[i] on arrays far larger than the
//     caches: the memory bandwidth one process draws, the limit the lattice
//     Boltzmann kernel is measured against. Counts 3 x 8 bytes per element
//     (as STREAM does; write-allocate traffic not counted) and reports the
//     best of several repetitions in GB/s (1e9 bytes/s).
//
//     Usage: streamTriad [million elements per array, default 80]
//------------------------------------------------------------------------------
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv)
{
    const long n = (argc > 1 ? std::atol(argv[1]) : 80)*1000000L;
    std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
    const double s = 3.0;
    double best = 1e30;
    for (int rep = 0; rep < 10; ++rep)
    {
        const auto t0 = std::chrono::steady_clock::now();
        double* __restrict__ pa = a.data();
        const double* __restrict__ pb = b.data();
        const double* __restrict__ pc = c.data();
        for (long i = 0; i < n; ++i)
        {
            pa[i] = pb[i] + s*pc[i];
        }
        const double dt =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
           .count();
        if (dt < best) best = dt;
    }
    // Keep the result alive
    double sum = 0;
    for (long i = 0; i < n; i += 4096) sum += a[i];
    std::printf("triad %.2f GB/s (best of 10, %ld elements, check %g)\n",
                3.0*8.0*n/best/1e9, n, sum);
    return 0;
}
