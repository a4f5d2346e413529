// Random numbers for the study, one independent stream per simulation, so that a
// simulation's draws depend only on (--seed, analysis, simulation index) and never on
// how the simulations are shared among threads.
//
// The engine is SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014), written here by hand because no packaged engine is cheap to
// seed 60,000 times (a Mersenne Twister fills 312 words per seed) and splittable by a
// counter. It passes BigCrush; its output feeds Boost.Random's distributions, whose
// algorithms, unlike std::uniform_real_distribution's, are the same on every platform.
#pragma once

#include <cstdint>
#include <limits>

namespace aloft::host {

class SimulationRandom {
 public:
  using result_type = std::uint64_t;

  // The stream of simulation `index` of analysis `stream` under the user's seed.
  SimulationRandom(std::uint64_t seed, std::uint64_t stream, std::uint64_t index)
      : state_(mix(mix(mix(seed) ^ (stream + 0x632be59bd9b4e019ULL)) ^ index)) {}

  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }

  result_type operator()() {
    state_ += 0x9e3779b97f4a7c15ULL;
    return mix(state_);
  }

 private:
  // The SplitMix64 output function (a variant of MurmurHash3's finaliser).
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  std::uint64_t state_;
};

}  // namespace aloft::host
