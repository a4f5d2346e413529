// `aloft replay --fifo FIFO.bin --odr-hz N` reads its file here: the bytes read from the
// ICM-42688-P's FIFO_DATA register in the configuration the firmware driver sets (SPEC §5:
// packet 3, 16 bytes, big-endian, ±16 g, ±2000 °/s, absolute 1 µs time stamps), as many
// bursts concatenated, decoded by the firmware's own decoder (aloft/sensor/icm42688p_fifo.hpp,
// in float) into a Recording: format "icm42688p_fifo", the first valid packet at t = 0.
//
// Time stamps count nominal microseconds (the chip on its PLL or an external clock)
// unless `clock` says internal_rc (ticks of 32/30 µs, datasheet §12.7). Gaps (packets
// missing from the file) are measured from the stamps, exact up to one wrap of the 16-bit
// stamp (65.536 ms); a file holds no other clock, so a longer hole is under-measured by
// whole wraps (the firmware driver measures those with the MCU clock).
//
// Faults, walked past with the firmware's own rules (aloft/sensor/icm42688p_fifo.hpp, next()),
// each counted in the Recording and none an error:
//   - HEADER_MSG (0x80, DS-000347 §6.2 "FIFO is empty"): an empty read, the byte alone or
//     its whole 16-byte slot; counted in empty_reads.
//   - a foreign header: skipped to the next packet boundary that two packets (headers 16
//     bytes apart, stamps one period apart) confirm (FifoDecoder::resync_bytes); counted
//     in resyncs, the bytes in bytes_skipped, a warning names the offset. The driver
//     resyncs by flushing the FIFO; a file has no flush, so the boundary is searched for,
//     and confirmed so that a data byte that looks like a header (0x68 is also a gyro's
//     high byte at 28 rad/s) does not make up samples.
//   - a cut last packet (power lost mid-burst): a warning naming its offset, its bytes in
//     bytes_skipped; everything before it is kept.
// aloft::host::Error, one line naming the file and the byte offset, only where nothing
// decodes: an empty file, no packet 3 at all, or no packet with data.
#pragma once

#include <string>

#include "aloft/sensor/icm42688p_fifo.hpp"
#include "replay/recording.hpp"

namespace aloft::host {

Recording read_fifo_recording(const std::string& path, double odr_hz,
                              icm42688p::TimestampClock clock = icm42688p::TimestampClock::pll_or_external);

}  // namespace aloft::host
