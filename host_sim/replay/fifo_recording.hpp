// `aloft replay --fifo FIFO.bin --odr-hz N` reads its file here: the bytes read from the
// ICM-42688-P's FIFO_DATA register in the configuration the firmware driver sets (SPEC §5:
// packet 3, 16 bytes, big-endian, ±16 g, ±2000 °/s, absolute 1 µs time stamps), as many
// bursts concatenated, decoded by the firmware's own decoder (aloft/icm42688p_fifo.hpp,
// in float) into a Recording: format "icm42688p_fifo", the first valid packet at t = 0.
//
// Time stamps count nominal microseconds (the chip on its PLL or an external clock)
// unless `clock` says internal_rc (ticks of 32/30 µs, datasheet §12.7). Gaps (packets
// missing from the file) are measured from the stamps, exact up to one wrap of the 16-bit
// stamp (65.536 ms); a file holds no other clock, so a longer hole is under-measured by
// whole wraps (the firmware driver measures those with the MCU clock).
//
// What the file must be, or aloft::host::Error with one line naming the file and the byte
// offset: not empty; a whole number of 16-byte packets (a truncated last packet is
// refused); every header packet 3 (0x68-0x6B); at least one packet with data.
//
// A foreign header is refused, not resynchronised past (so bytes_skipped stays 0). The
// firmware driver can resync because it flushes the FIFO and the chip restarts on a packet
// boundary; a file has no flush. After a foreign header nothing marks where the next
// packet starts — the header value 0x68 is also a common data byte — so any resync would
// be a guess of the alignment, and a wrong guess turns data bytes into made-up samples.
// The contract is one line and exit 2 for a foreign header: a replay must never
// report a flight from bytes it had to guess at.
#pragma once

#include <string>

#include "aloft/icm42688p_fifo.hpp"
#include "replay/recording.hpp"

namespace aloft::host {

Recording read_fifo_recording(const std::string& path, double odr_hz,
                              icm42688p::TimestampClock clock = icm42688p::TimestampClock::pll_or_external);

}  // namespace aloft::host
