// The record ring under power cuts, tested the way littlefs tests itself: a sequence of
// flights is appended to a fake NOR flash (fake_flash.hpp) that cuts the power after
// every program and erase operation, inside every program at every byte, and inside
// every erase at every byte (the rest of the block keeps its old bytes) or with the
// block left as garbage. After each cut the ring is mounted again, and
//   - every record committed before the cut is there, unless its block's erase had begun;
//   - no record is invented: each one found is byte for byte a record that was committed;
//   - the next flight appends with a higher sequence number, and is found after a mount;
//   - mount read at most (block_count + 1) * block_size bytes;
//   - no program wrote a 1 over a 0.
// It prints how many cut points it exercised.
#include <cstdint>
#include <cstdio>

#include "aloft/records/record_ring.hpp"
#include "fake_flash.hpp"
#include "test_api.hpp"

#if defined(ALOFT_BARE_METAL_RUNNER)
#include "aloft_port/port.hpp"
#endif

namespace {

using aloft::FlightRecord;
using aloft::RecordRing;
using aloft::Status;
using aloft::testing::EraseCut;
using aloft::testing::FakeFlash;

FlightRecord flight(std::uint32_t i) {
  FlightRecord r;
  r.flight_number = i;
  r.release_us = 1000000ull * i + 17;
  r.landing_us = r.release_us + 812345 + i;
  r.samples = 800 + i;
  r.gaps = i % 3;
  r.clipped_samples = i % 5;
  r.landed = i % 4 != 3;
  r.turned = i % 7 != 0;
  r.comparisons = 5000 + i;
  r.rms_da_rad = 0.01f * static_cast<float>(i + 1);
  r.rms_rel_err = 0.002f * static_cast<float>(i + 1);
  r.seeds_stored = i % 5;
  for (std::uint32_t s = 0; s < r.seeds_stored; ++s) r.seeds[s] = {0.001f * static_cast<float>(s + i), 0.5f};
  r.tensor_hash = 0xA5A50000u + i;
  r.settings_hash = 0x5A5A0000u ^ i;
  return r;
}

bool same_record(const FlightRecord& a, const FlightRecord& b) {
  std::uint8_t x[aloft::flight_record_size], y[aloft::flight_record_size];
  aloft::encode_flight_record(a, x);
  aloft::encode_flight_record(b, y);
  return aloft::bytes_equal(x, y, aloft::flight_record_size);
}

// What the test knows was written: required when the commit marker's program call
// returned; optional when the power was cut inside that call (the marker may be whole).
struct Committed {
  std::uint32_t sequence, flight, block, erase_count;
  bool required;
};

struct Model {
  static constexpr std::uint32_t capacity = 64;
  Committed entries[capacity];
  std::uint32_t count = 0;
  std::uint32_t highest = 0;

  // The latest entry: a number whose record was torn before its marker goes to the next.
  const Committed* find(std::uint32_t sequence) const {
    for (std::uint32_t i = count; i-- > 0;)
      if (entries[i].sequence == sequence) return &entries[i];
    return nullptr;
  }
};

template <typename Flash>
Status append_flight(Flash& flash, RecordRing& ring, Model& model, std::uint32_t i) {
  const std::uint32_t programs = flash.completed_programs();
  FlightRecord r = flight(i);
  const Status s = ring.append(r);
  const auto is_commit = [](const auto& program) {
    return program.offset % aloft::flight_record_size == aloft::flight_record_commit_offset;
  };
  const bool committed = flash.completed_programs() > programs && is_commit(flash.last_program());
  const bool maybe =
      !flash.powered() && !flash.cut_was_erase() && is_commit(flash.cut_operation()) && !committed;
  if ((committed || maybe) && model.count < Model::capacity) {
    const std::uint32_t block = committed ? flash.last_program().block : flash.cut_operation().block;
    model.entries[model.count++] = {r.sequence, i, block, flash.erase_count(block), committed};
    if (committed && r.sequence > model.highest) model.highest = r.sequence;
  }
  return s;
}

// Mounts and compares what is stored with the model; returns the mounted ring's state.
template <std::uint32_t B, std::uint32_t N>
void check_contents(FakeFlash<B, N>& flash, const Model& model, RecordRing& ring) {
  const std::uint64_t read_before = flash.bytes_read();
  ALOFT_REQUIRE(ring.mount() == Status::ok);
  ALOFT_CHECK(flash.bytes_read() - read_before <= std::uint64_t(N + 1) * B);
  bool seen[Model::capacity] = {};
  std::uint32_t invented = 0, duplicated = 0;
  const Status s = ring.for_each_record([&](const FlightRecord& r, std::uint32_t, std::uint32_t) {
    const Committed* c = model.find(r.sequence);
    FlightRecord expected = c ? flight(c->flight) : FlightRecord();
    expected.sequence = r.sequence;
    if (c == nullptr || !same_record(r, expected)) return void(++invented);
    bool& was_seen = seen[c - model.entries];
    if (was_seen) ++duplicated;
    was_seen = true;
  });
  ALOFT_CHECK(s == Status::ok);
  std::uint32_t missing = 0;
  for (std::uint32_t i = 0; i < model.count; ++i) {
    const Committed& c = model.entries[i];
    if (c.required && flash.erase_count(c.block) == c.erase_count && !seen[i]) ++missing;
  }
  ALOFT_CHECK(invented == 0u);
  ALOFT_CHECK(duplicated == 0u);
  ALOFT_CHECK(missing == 0u);
  ALOFT_CHECK(ring.next_sequence() > model.highest);
}

struct Cut {
  std::uint32_t op, bytes;
  EraseCut how;
};

struct CutCounts {
  std::uint32_t after_operation = 0, inside_program = 0, inside_erase = 0, operations = 0;
  std::uint32_t erases = 0;
  bool last_op_was_erase = false;
  std::uint32_t last_op_size = 0;
};

// Appends `flights` flights until the cut, powers on, checks, appends one more, checks.
// Returns false when the run ended before operation cut.op (no such operation).
template <std::uint32_t B, std::uint32_t N>
bool run_with_cut(FakeFlash<B, N>& flash, std::uint32_t flights, const Cut& cut, CutCounts& counts) {
  flash.reset();
  flash.schedule_cut(cut.op, cut.bytes, cut.how);
  Model model;
  RecordRing ring(flash.device());
  ALOFT_REQUIRE(ring.mount() == Status::ok);
  std::uint32_t i = 0;
  for (; i < flights && flash.powered(); ++i) {
    const Status s = append_flight(flash, ring, model, i);
    ALOFT_REQUIRE((s == Status::ok || !flash.powered()));
  }
  if (flash.powered()) return false;
  counts.last_op_was_erase = flash.cut_was_erase();
  counts.last_op_size = flash.cut_operation().size;
  flash.power_on();
  RecordRing after_cut(flash.device());
  check_contents(flash, model, after_cut);
  ALOFT_CHECK(append_flight(flash, after_cut, model, i) == Status::ok);
  ALOFT_CHECK((model.count > 0u && model.entries[model.count - 1].flight == i));
  RecordRing after_append(flash.device());
  check_contents(flash, model, after_append);
  ALOFT_CHECK(flash.violations() == 0u);
  return true;
}

// Every operation of the uncut run, cut after it and inside it at every byte.
template <std::uint32_t B, std::uint32_t N>
CutCounts cut_everywhere(std::uint32_t program_size, std::uint32_t flights, std::uint32_t erase_stride) {
  FakeFlash<B, N> flash(program_size);
  CutCounts counts;
  for (std::uint32_t op = 0; run_with_cut(flash, flights, {op, flash.never, EraseCut::prefix_erased}, counts);
       ++op) {
    ++counts.after_operation;
    const bool erase = counts.last_op_was_erase;
    const std::uint32_t size = counts.last_op_size;
    counts.erases += erase ? 1 : 0;
    for (std::uint32_t j = 0; j < size; j += erase ? erase_stride : 1) {
      ALOFT_CHECK(run_with_cut(flash, flights, {op, j, EraseCut::prefix_erased}, counts));
      ++(erase ? counts.inside_erase : counts.inside_program);
    }
    if (erase) {
      ALOFT_CHECK(run_with_cut(flash, flights, {op, 0, EraseCut::garbage}, counts));
      ++counts.inside_erase;
    }
  }
  // The uncut run: the same operations, and enough flights to wrap the ring.
  flash.reset();
  Model model;
  RecordRing ring(flash.device());
  ALOFT_REQUIRE(ring.mount() == Status::ok);
  for (std::uint32_t i = 0; i < flights; ++i)
    ALOFT_REQUIRE(append_flight(flash, ring, model, i) == Status::ok);
  counts.operations = flash.operations();
  ALOFT_CHECK(counts.after_operation == counts.operations);
  ALOFT_CHECK(flash.erase_count(0) >= 3u);  // wrapped at least twice after the first erase
  return counts;
}

// Text without printf (newlib's may reach for the heap on the target).
struct Line {
  char text[240] = {};
  std::uint32_t length = 0;
  Line& operator<<(const char* s) {
    while (*s && length + 1 < sizeof(text)) text[length++] = *s++;
    return *this;
  }
  Line& operator<<(std::uint32_t v) {
    char digits[12];
    int n = 0;
    do digits[n++] = static_cast<char>('0' + v % 10), v /= 10;
    while (v != 0);
    while (n > 0 && length + 1 < sizeof(text)) text[length++] = digits[--n];
    return *this;
  }
};

void print_counts(const char* geometry, const CutCounts& c) {
  Line line;
  line << "power-cut test " << geometry << ": " << c.operations << " operations (" << c.erases
       << " erases); cut after each: " << c.after_operation
       << "; inside programs at every byte: " << c.inside_program << "; inside erases: " << c.inside_erase
       << "; total cut points: " << (c.after_operation + c.inside_program + c.inside_erase) << "\n";
#if defined(ALOFT_BARE_METAL_RUNNER)
  aloft::port::write_text(line.text);
#else
  std::fputs(line.text, stdout);
#endif
}

}  // namespace

#if defined(ALOFT_BARE_METAL_RUNNER)
// Under QEMU: a smaller ring (2 slots per block), the same cuts.
ALOFT_TEST_CASE("record ring: a power cut at every operation and every byte", "[records]") {
  const CutCounts c = cut_everywhere<256, 3>(4, 20, 1);
  print_counts("3 blocks x 2 slots, program unit 4, 20 flights", c);
  ALOFT_CHECK(c.inside_program == 20u * (120u + 4u));
  ALOFT_CHECK(c.inside_erase == c.erases * (256u + 1u));
}
#else
ALOFT_TEST_CASE("record ring: a power cut at every operation and every byte", "[records]") {
  const CutCounts a = cut_everywhere<512, 3>(4, 40, 1);
  print_counts("3 blocks x 4 slots, program unit 4, 40 flights", a);
  ALOFT_CHECK(a.inside_program == 40u * (120u + 4u));
  ALOFT_CHECK(a.inside_erase == a.erases * (512u + 1u));
  const CutCounts b = cut_everywhere<256, 2>(1, 16, 1);
  print_counts("2 blocks x 2 slots, program unit 1, 16 flights", b);
  ALOFT_CHECK(b.inside_program == 16u * (120u + 4u));
  const CutCounts c = cut_everywhere<384, 4>(8, 40, 1);
  print_counts("4 blocks x 3 slots, program unit 8, 40 flights", c);
  ALOFT_CHECK(c.inside_program == 40u * (120u + 8u));
}
#endif
