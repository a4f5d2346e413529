// write_example_records OUT.bin: writes the example dump of the record area
// (examples/flight_records.bin; example_flights.hpp says what is in it). Regenerate with
//   build/host/tests/records/write_example_records examples/flight_records.bin
#include <cstdio>

#include "example_flights.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_example_records OUT.bin\n");
    return 2;
  }
  const aloft::Status s = aloft::test::write_example_dump(argv[1]);
  if (s != aloft::Status::ok) {
    std::fprintf(stderr, "write_example_records: %s\n", aloft::describe(s));
    return 1;
  }
  return 0;
}
