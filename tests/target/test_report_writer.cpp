// The heap-free number formatting every target report goes through
// (aloft_port/report_writer.hpp): what it writes is what the example test parses.
#include <cstring>

#include "aloft_port/report_writer.hpp"
#include "test_api.hpp"

namespace {

char captured[128];

void capture(const char* text) {
  const std::size_t used = std::strlen(captured);
  std::strncat(captured, text, sizeof(captured) - used - 1);
}

aloft::port::ReportWriter fresh_writer() {
  captured[0] = '\0';
  return aloft::port::ReportWriter(capture);
}

bool wrote(const char* expected) { return std::strcmp(captured, expected) == 0; }

}  // namespace

ALOFT_TEST_CASE("integers are written in full, sign included", "[target][report]") {
  fresh_writer().integer(0);
  ALOFT_CHECK(wrote("0"));
  fresh_writer().integer(-42);
  ALOFT_CHECK(wrote("-42"));
  fresh_writer().integer(INT64_MIN);
  ALOFT_CHECK(wrote("-9223372036854775808"));
  fresh_writer().integer(4294967296);
  ALOFT_CHECK(wrote("4294967296"));
}

ALOFT_TEST_CASE("fixed-point numbers round half away from zero", "[target][report]") {
  fresh_writer().fixed(3.14159f, 3);
  ALOFT_CHECK(wrote("3.142"));
  fresh_writer().fixed(-0.0625f, 3);
  ALOFT_CHECK(wrote("-0.063"));
  fresh_writer().fixed(9.9996f, 3);  // the fraction carries into the integer part
  ALOFT_CHECK(wrote("10.000"));
  fresh_writer().fixed(2.5f, 0);
  ALOFT_CHECK(wrote("3"));
  fresh_writer().fixed(0.000123f, 6);
  ALOFT_CHECK(wrote("0.000123"));
  fresh_writer().fixed(123456.0f, 1);
  ALOFT_CHECK(wrote("123456.0"));
  fresh_writer().fixed(4.0e9f, 2);  // beyond 32 bits: the digits past 1e9 are zeros
  ALOFT_CHECK(wrote("4000000000.00"));
  fresh_writer().fixed(-1.0e12f, 0);
  ALOFT_CHECK(wrote("-1000000000000"));
}

ALOFT_TEST_CASE("non-finite numbers are named", "[target][report]") {
  fresh_writer().fixed(__builtin_nanf(""), 2);
  ALOFT_CHECK(wrote("nan"));
  fresh_writer().fixed(-__builtin_inff(), 2);
  ALOFT_CHECK(wrote("-inf"));
  fresh_writer().text("a").text("b").line();
  ALOFT_CHECK(wrote("ab\n"));
}

ALOFT_TEST_CASE("bytes are written as two upper-case hex digits", "[target][report]") {
  fresh_writer().hex_byte(0x00);
  ALOFT_CHECK(wrote("0x00"));
  fresh_writer().hex_byte(0x47).text(" ").hex_byte(0xFF);
  ALOFT_CHECK(wrote("0x47 0xFF"));
  fresh_writer().hex_byte(0xA5);
  ALOFT_CHECK(wrote("0xA5"));
}
