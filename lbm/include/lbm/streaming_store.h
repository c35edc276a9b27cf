#pragma once
// Stores of the collide-stream kernel's output that bypass the caches.
//
// A plain store first reads the destination cache line from memory (write-allocate), so a
// pull kernel that writes its 19 populations with plain stores moves 3 x 19 values per
// update instead of 2 x 19. A non-temporal (streaming) store writes a whole line without
// reading it. It needs whole, aligned lines: the head and the tail of a range that do not
// fill a line keep plain stores. Without AVX the plain loop is all there is; the values
// written are the same either way (only the way they reach memory changes).
#include <cstddef>
#include <cstdint>

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
#endif

// to[i] = Real(from[i]) for i < m; whole cache lines of `to` written with streaming stores.
// `from` is the kernel's 64-byte aligned double buffer. Call streaming_store_fence() before
// another thread may read what was stored.
template <typename Real>
inline void streaming_store(Real* __restrict to, const double* __restrict from, int m) {
  constexpr int kPerLine = int(kCacheLine / sizeof(Real));
  const auto address = reinterpret_cast<std::uintptr_t>(to);
  int head = int((kCacheLine - address % kCacheLine) % kCacheLine / sizeof(Real));
  if (address % sizeof(Real) != 0 || head > m) head = m;  // no whole line to stream
  const int body_end = head + (m - head) / kPerLine * kPerLine;
#if defined(__AVX512F__)
  if constexpr (sizeof(Real) == 8) {  // head and tail as one masked store each
    double* out = reinterpret_cast<double*>(to);
    if (head > 0) _mm512_mask_storeu_pd(out, __mmask8((1u << head) - 1), _mm512_loadu_pd(from));
    for (int i = head; i < body_end; i += kPerLine)
      _mm512_stream_pd(out + i, _mm512_loadu_pd(from + i));
    if (body_end < m)
      _mm512_mask_storeu_pd(out + body_end, __mmask8((1u << (m - body_end)) - 1),
                            _mm512_loadu_pd(from + body_end));
    return;
  }
#endif
  for (int i = 0; i < head; ++i) to[i] = static_cast<Real>(from[i]);
#if defined(__AVX512F__) || defined(__AVX__)
  for (int i = head; i < body_end; i += kPerLine) {
    if constexpr (sizeof(Real) == 8) {
      _mm256_stream_pd(reinterpret_cast<double*>(to + i), _mm256_loadu_pd(from + i));
      _mm256_stream_pd(reinterpret_cast<double*>(to + i + 4), _mm256_loadu_pd(from + i + 4));
    } else {
      for (int h = 0; h < kPerLine; h += 8)
        _mm256_stream_ps(reinterpret_cast<float*>(to + i + h), to_float8(from + i + h));
    }
  }
#else
  for (int i = head; i < body_end; ++i) to[i] = static_cast<Real>(from[i]);
#endif
  for (int i = body_end; i < m; ++i) to[i] = static_cast<Real>(from[i]);
}

// Orders this thread's streaming stores before its later stores (they are weakly ordered),
// so that the threads that read the array after the kernel see them.
inline void streaming_store_fence() {
#if defined(__AVX512F__) || defined(__AVX__)
  _mm_sfence();
#endif
}

}  // namespace lbm::detail
