#pragma once
// Stores of the collide-stream kernel's output that bypass the caches.
//
// A plain store first reads the destination cache line from memory (write-allocate), so a
// pull kernel that writes its 19 populations with plain stores moves 3 x 19 values per
// update instead of 2 x 19 when its arrays do not fit in the cache. A non-temporal
// (streaming) store writes without reading: whole, aligned lines as one vector store each,
// and the head and the tail of a range that do not fill a line as one 8- or 4-byte
// non-temporal store (movnti) per value (a plain store into a line that is not in the cache
// holds the store buffer until that line has been read: that cost the kernel a third of its
// time at 128^3, measured with bench_lbm, doc/performance.md). Other threads may write the
// rest of a head's or a tail's line: the non-temporal stores write only their own bytes, as
// plain ones do.
// Arrays that fit in the cache are written with plain stores instead (collide_stream.cpp):
// streamed, they would be read back from memory by the next step. Without AVX the plain
// loop is all there is; the values written are the same either way (only the way they
// reach memory changes).
#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__AVX512F__) || defined(__AVX__)
#include <immintrin.h>
#endif

namespace lbm::detail {

constexpr std::size_t kCacheLine = 64;

#if defined(__AVX512F__) || defined(__AVX__)
// Eight doubles rounded to float as static_cast<float> does (round to nearest).
inline __m256 to_float8(const double* from) {
#if defined(__AVX512F__)
  return _mm512_cvtpd_ps(_mm512_loadu_pd(from));
#else
  return _mm256_set_m128(_mm256_cvtpd_ps(_mm256_loadu_pd(from + 4)),
                         _mm256_cvtpd_ps(_mm256_loadu_pd(from)));
#endif
}

// One value, non-temporal (movnti stores a general register: its bits are the value's).
inline void stream_value(double* to, double value) {
  long long bits;
  std::memcpy(&bits, &value, sizeof bits);
  _mm_stream_si64(reinterpret_cast<long long*>(to), bits);
}
inline void stream_value(float* to, double value) {
  const float rounded = static_cast<float>(value);
  int bits;
  std::memcpy(&bits, &rounded, sizeof bits);
  _mm_stream_si32(reinterpret_cast<int*>(to), bits);
}

// One whole, aligned cache line.
inline void stream_line(double* to, const double* from) {
#if defined(__AVX512F__)
  _mm512_stream_pd(to, _mm512_loadu_pd(from));
#else
  _mm256_stream_pd(to, _mm256_loadu_pd(from));
  _mm256_stream_pd(to + 4, _mm256_loadu_pd(from + 4));
#endif
}
inline void stream_line(float* to, const double* from) {
  _mm256_stream_ps(to, to_float8(from));
  _mm256_stream_ps(to + 8, to_float8(from + 8));
}
#endif

#if defined(__AVX512F__) || defined(__AVX__)
// Stores the head of to[0, m) (up to its first line boundary) and the whole lines after
// it; returns where the tail that does not fill a line starts.
template <typename Real>
inline int store_head_and_lines(Real* __restrict to, const double* __restrict from, int m) {
  constexpr int kPerLine = int(kCacheLine / sizeof(Real));
  const auto address = reinterpret_cast<std::uintptr_t>(to);
  int head = int((kCacheLine - address % kCacheLine) % kCacheLine / sizeof(Real));
  if (address % sizeof(Real) != 0 || head > m) head = m;  // no whole line to stream
  const int body_end = head + (m - head) / kPerLine * kPerLine;
  for (int i = 0; i < head; ++i) stream_value(to + i, from[i]);
  for (int i = head; i < body_end; i += kPerLine) stream_line(to + i, from + i);
  return body_end;
}
#endif

// to[i] = Real(from[i]) for i < m, all with non-temporal stores: the whole lines as one
// vector store each, the head and the tail value by value. `from` is the kernel's 64-byte
// aligned double buffer. Call streaming_store_fence() before another thread may read what
// was stored.
template <typename Real>
inline void streaming_store(Real* __restrict to, const double* __restrict from, int m) {
#if defined(__AVX512F__) || defined(__AVX__)
  for (int i = store_head_and_lines(to, from, m); i < m; ++i) stream_value(to + i, from[i]);
#else
  for (int i = 0; i < m; ++i) to[i] = static_cast<Real>(from[i]);
#endif
}

// One chunk of a run of chunks that write consecutive ranges of one stream (the kernel's
// runs over several rows): as streaming_store, except that a tail which does not fill its
// line is not stored unless `last`. The count of those values is returned; the caller
// passes them again at the head of the next chunk, whose range then starts on that line's
// boundary, so that inside a run every line is stored whole, by one vector store.
template <typename Real>
inline int streaming_store_keep_tail(Real* __restrict to, const double* __restrict from, int m,
                                     bool last) {
#if defined(__AVX512F__) || defined(__AVX__)
  if (!last) return m - store_head_and_lines(to, from, m);
#else
  (void)last;
#endif
  streaming_store(to, from, m);
  return 0;
}

// Orders this thread's streaming stores before its later stores (they are weakly ordered),
// so that the threads that read the array after the kernel see them.
inline void streaming_store_fence() {
#if defined(__AVX512F__) || defined(__AVX__)
  _mm_sfence();
#endif
}

}  // namespace lbm::detail
