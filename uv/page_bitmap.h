// Internal to uv/: a square page of texels as one bit per texel, row by row, with the two searches
// the packer skips along a row with: the first taken texel in a span, the first free one after a
// column. Both step 64 texels at a time.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace radbake {

class PageBitmap {
 public:
  explicit PageBitmap(int size)
      : size_(size), words_((size + 63) / 64), bits_(size_t(words_) * size_t(size), 0), runs_(size_t(size)) {}
  int size() const { return size_; }

  // The first taken column in [from, to] of row y, or -1. Columns must lie on the page.
  int first_taken(int y, int from, int to) const {
    const uint64_t* row = &bits_[size_t(y) * size_t(words_)];
    int w = from >> 6, last = to >> 6;
    uint64_t m = row[w] & (~uint64_t(0) << (from & 63));
    for (;;) {
      if (w == last) m &= ~uint64_t(0) >> (63 - (to & 63));
      if (m) return w * 64 + __builtin_ctzll(m);
      if (w == last) return -1;
      m = row[++w];
    }
  }

  // The first free column at or after `from` in row y, or size() when there is none.
  int first_free(int y, int from) const {
    if (from >= size_) return size_;
    const uint64_t* row = &bits_[size_t(y) * size_t(words_)];
    int w = from >> 6;
    uint64_t m = ~row[w] & (~uint64_t(0) << (from & 63));
    while (!m && ++w < words_) m = ~row[w];
    return w < words_ ? std::min(size_, w * 64 + __builtin_ctzll(m)) : size_;
  }

  // Marks [from, to] of row y taken; parts off the page are ignored.
  void take(int y, int from, int to) {
    if (y < 0 || y >= size_) return;
    from = std::max(from, 0), to = std::min(to, size_ - 1);
    uint64_t* row = &bits_[size_t(y) * size_t(words_)];
    runs_[size_t(y)].clear();
    for (int x = from; x <= to;) {
      int w = x >> 6, end = std::min(to, w * 64 + 63);
      uint64_t m = (~uint64_t(0) << (x & 63)) & (~uint64_t(0) >> (63 - (end & 63)));
      row[w] |= m;
      x = end + 1;
    }
  }

  // Narrows `fits`, one bit per column x of words [w0, w1] (the caller's), to the columns x for
  // which texels [x + first, x + first + length - 1] of row y are all free: a whole row at once,
  // from where runs of 2^k free texels start, kept per row until the row changes.
  void keep_fitting(int y, int first, int length, uint64_t* fits, int w0, int w1) const {
    int level = 0;
    while (level + 1 < kRunLevels && (2 << level) <= length) ++level;
    const int step = 1 << level;
    const uint64_t* run = runs(y, level);
    for (int w = w0; w <= w1; ++w) {
      if (!fits[w]) continue;
      const int p = (w << 6) + first;
      uint64_t m = bits_at(run, p) & bits_at(run, p + length - step);
      for (int offset = step; offset < length - step; offset += step) m &= bits_at(run, p + offset);
      fits[w] &= m;
    }
  }

  // The longest run of free texels in row y.
  int longest_free_run(int y) const {
    int longest = 0;
    for (int x = first_free(y, 0); x < size_;) {
      int taken = first_taken(y, x, size_ - 1);
      int end = taken < 0 ? size_ : taken;
      longest = std::max(longest, end - x);
      x = end < size_ ? first_free(y, end) : size_;
    }
    return longest;
  }

 private:
  static constexpr int kRunLevels = 6;  // runs of 1, 2, 4, ... 32 free texels

  // Where in row y runs of 2^level free texels start, one bit per column.
  const uint64_t* runs(int y, int level) const {
    std::vector<uint64_t>& r = runs_[size_t(y)];
    if (r.empty()) {
      r.resize(size_t(kRunLevels) * size_t(words_));
      const uint64_t* row = &bits_[size_t(y) * size_t(words_)];
      for (int w = 0; w < words_; ++w) r[size_t(w)] = ~row[w];
      if (size_ & 63) r[size_t(words_ - 1)] &= ~uint64_t(0) >> (64 - (size_ & 63));
      for (int k = 1; k < kRunLevels; ++k) {
        const uint64_t* below = &r[size_t(k - 1) * size_t(words_)];
        for (int w = 0; w < words_; ++w) r[size_t(k) * size_t(words_) + size_t(w)] = below[w] & bits_at(below, (w << 6) + (1 << (k - 1)));
      }
    }
    return &r[size_t(level) * size_t(words_)];
  }

  // 64 bits of a row's words from bit p on; bits past the row read as 0.
  uint64_t bits_at(const uint64_t* v, int p) const {
    const int i = p >> 6, o = p & 63;
    const uint64_t low = i < words_ ? v[i] >> o : 0;
    const uint64_t high = o && i + 1 < words_ ? v[i + 1] << (64 - o) : 0;
    return low | high;
  }

  int size_, words_;
  std::vector<uint64_t> bits_;
  mutable std::vector<std::vector<uint64_t>> runs_;  // per row: runs() of each level, or empty
};

}  // namespace radbake
