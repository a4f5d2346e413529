// Catch2's main, compiled once for every host and armhf test program. Doubles are
// shown with 17 digits, so a failed accuracy check shows the measured figure in full.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char* argv[]) {
  Catch::StringMaker<double>::precision = 17;
  Catch::StringMaker<float>::precision = 9;
  return Catch::Session().run(argc, argv);
}
