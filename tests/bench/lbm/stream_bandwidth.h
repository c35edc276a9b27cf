#pragma once
#include <cstddef>
// Sustainable memory bandwidth of this machine, measured like STREAM's "copy" kernel
// (bytes counted: one read and one write per element, no write-allocate), on arrays far
// larger than the caches. Benchmarks divide it by their own bytes per update, counted the
// same way, to get the roofline limit they are compared with.
// kPlain: plain stores, which first read the destination line (write-allocate), so the copy
// moves 3 bytes for the 2 it counts; kStreaming: streaming stores, 2 moved for 2 counted.
enum class CopyStores { kPlain, kStreaming };
double measure_copy_bandwidth(int threads, CopyStores stores,
                              std::size_t bytes_per_array = std::size_t(1) << 28);
