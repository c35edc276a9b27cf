#pragma once
#include <cstddef>
// Sustainable memory bandwidth of this machine, measured like STREAM's "copy" kernel
// (bytes counted: one read and one write per element, no write-allocate), on arrays far
// larger than the caches. Benchmarks divide it by their own bytes per update, counted the
// same way, to get the roofline limit they are compared with.
double measure_copy_bandwidth(int threads, std::size_t bytes_per_array = std::size_t(1) << 28);
