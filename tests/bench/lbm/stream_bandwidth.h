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

// One array read and written back in place, a[i] = s a[i] + t (bytes counted: one read and
// one write per element, and that is what moves: the stores hit lines just read, so there
// is no write-allocate). The access of the in-place (AA pattern) kernel, one array instead
// of its 19.
double measure_update_bandwidth(int threads, std::size_t bytes_per_array = std::size_t(1) << 28);

// The same copy over `arrays` source arrays into as many destination arrays of
// `values_per_array` doubles each, with streaming stores, array after array in bursts of
// `burst` values (the most favourable order for the memory: one stream at a time, long
// runs): what a kernel that reads 19 population arrays and writes 19 can move at most on
// this machine, whatever it computes. Bytes counted as above (one read, one write).
double measure_multi_array_copy_bandwidth(int threads, int arrays, std::size_t values_per_array,
                                          std::size_t burst);
