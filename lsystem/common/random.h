#pragma once
// Counter-based random numbers: every draw is a pure function of
// (seed, step, module position, draw index), so a derivation gives the same
// result whatever the number of threads or the order modules are visited in.

#include <cmath>
#include <cstdint>
#include <numbers>

namespace lsys {

constexpr uint64_t splitmix64(uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// The stream of draws belonging to one module in one rewriting pass.
struct RandomStream {
    uint64_t key = 0;
    uint64_t draw = 0;

    static RandomStream forModule(uint64_t seed, uint64_t pass, uint64_t position) {
        return {splitmix64(splitmix64(splitmix64(seed) ^ pass) ^ position), 0};
    }

    // Uniform in [0, 1).
    double uniform() { return static_cast<double>(splitmix64(key ^ splitmix64(draw++)) >> 11) * 0x1.0p-53; }

    // Normal distribution (Box-Muller on two uniform draws).
    double normal(double mean, double sd) {
        double u1 = 1.0 - uniform(); // in (0, 1], keeps log finite
        double u2 = uniform();
        return mean + sd * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }
};

} // namespace lsys
