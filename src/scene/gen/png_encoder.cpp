// Deterministic PNG writer: row filters, LZ77 + fixed-Huffman deflate, zlib and PNG framing.
#include "scene/gen/png_encoder.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <string>

#include "util/error.h"

namespace ontile::gen {
namespace {

constexpr int kBytesPerPixel = 3;

// LSB-first bit packing (RFC 1951 3.1.1); Huffman codes are sent most significant bit first.
class BitWriter {
 public:
  explicit BitWriter(std::vector<uint8_t>& out) : out_(out) {}
  void put_bits(uint32_t value, int count) {
    buffer_ |= value << count_;
    count_ += count;
    while (count_ >= 8) {
      out_.push_back(static_cast<uint8_t>(buffer_ & 0xFFu));
      buffer_ >>= 8;
      count_ -= 8;
    }
  }
  void put_code(uint32_t code, int length) {
    uint32_t reversed = 0;
    for (int i = 0; i < length; ++i) reversed |= ((code >> i) & 1u) << (length - 1 - i);
    put_bits(reversed, length);
  }
  void flush() {
    if (count_ > 0) out_.push_back(static_cast<uint8_t>(buffer_ & 0xFFu));
    buffer_ = 0;
    count_ = 0;
  }

 private:
  std::vector<uint8_t>& out_;
  uint32_t buffer_ = 0;
  int count_ = 0;
};

// Fixed literal/length code (RFC 1951 3.2.6).
void put_literal_length_symbol(BitWriter& bits, int symbol) {
  if (symbol <= 143) bits.put_code(0x30u + symbol, 8);
  else if (symbol <= 255) bits.put_code(0x190u + (symbol - 144), 9);
  else if (symbol <= 279) bits.put_code(static_cast<uint32_t>(symbol - 256), 7);
  else bits.put_code(0xC0u + (symbol - 280), 8);
}

constexpr std::array<int, 29> kLengthBase = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,
                                             15, 17, 19, 23, 27, 31, 35, 43, 51,  59,
                                             67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<int, 29> kLengthExtra = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                              2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr std::array<int, 30> kDistanceBase = {
    1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
    193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr std::array<int, 30> kDistanceExtra = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                                6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

void put_match(BitWriter& bits, int length, int distance) {
  int l = 28;
  while (kLengthBase[l] > length) --l;
  put_literal_length_symbol(bits, 257 + l);
  bits.put_bits(static_cast<uint32_t>(length - kLengthBase[l]), kLengthExtra[l]);
  int d = 29;
  while (kDistanceBase[d] > distance) --d;
  bits.put_code(static_cast<uint32_t>(d), 5);  // fixed distance codes are 5-bit d
  bits.put_bits(static_cast<uint32_t>(distance - kDistanceBase[d]), kDistanceExtra[d]);
}

// One final fixed-Huffman block over greedy LZ77 matches (hash chains on 3-byte prefixes).
void deflate_fixed(const std::vector<uint8_t>& data, std::vector<uint8_t>& out) {
  constexpr int kHashBits = 15, kWindow = 32768, kMinMatch = 3, kMaxMatch = 258, kMaxChain = 48;
  const int n = static_cast<int>(data.size());
  std::vector<int> head(1 << kHashBits, -1), previous(data.size(), -1);
  const auto hash_at = [&](int pos) {
    const uint32_t key = (uint32_t{data[pos]} << 16) | (uint32_t{data[pos + 1]} << 8) | data[pos + 2];
    return (key * 2654435761u) >> (32 - kHashBits);
  };
  const auto insert = [&](int pos) {
    if (pos + kMinMatch > n) return;
    const uint32_t h = hash_at(pos);
    previous[pos] = head[h];
    head[h] = pos;
  };
  BitWriter bits(out);
  bits.put_bits(1, 1);  // BFINAL
  bits.put_bits(1, 2);  // BTYPE = 01, fixed Huffman codes
  int pos = 0;
  while (pos < n) {
    int best_length = 0, best_distance = 0;
    if (pos + kMinMatch <= n) {
      const int limit = std::min(kMaxMatch, n - pos);
      int candidate = head[hash_at(pos)];
      for (int chain = 0; candidate >= 0 && pos - candidate <= kWindow && chain < kMaxChain;
           ++chain, candidate = previous[candidate]) {
        int length = 0;
        while (length < limit && data[candidate + length] == data[pos + length]) ++length;
        if (length > best_length) {
          best_length = length;
          best_distance = pos - candidate;
          if (length == limit) break;
        }
      }
    }
    if (best_length >= kMinMatch) {
      put_match(bits, best_length, best_distance);
      for (int i = 0; i < best_length; ++i) insert(pos + i);
      pos += best_length;
    } else {
      put_literal_length_symbol(bits, data[pos]);
      insert(pos);
      ++pos;
    }
  }
  put_literal_length_symbol(bits, 256);  // end of block
  bits.flush();
}

uint32_t adler32(const std::vector<uint8_t>& data) {
  uint32_t a = 1, b = 0;
  for (uint8_t byte : data) {
    a = (a + byte) % 65521u;
    b = (b + a) % 65521u;
  }
  return (b << 16) | a;
}

uint32_t crc32(const uint8_t* data, size_t size) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  uint32_t crc = 0xFFFFFFFFu;
  for (size_t i = 0; i < size; ++i) crc = table[(crc ^ data[i]) & 0xFFu] ^ (crc >> 8);
  return crc ^ 0xFFFFFFFFu;
}

void put_u32_be(std::vector<uint8_t>& out, uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(value >> shift));
}

void put_chunk(std::vector<uint8_t>& out, const char type[4], const std::vector<uint8_t>& data) {
  put_u32_be(out, static_cast<uint32_t>(data.size()));
  const size_t type_offset = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  put_u32_be(out, crc32(out.data() + type_offset, out.size() - type_offset));
}

int paeth(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

// Filtered scanlines, each prefixed by its filter type byte (PNG spec 9.2).
std::vector<uint8_t> filter_rows(const RgbImage& image) {
  const size_t stride = static_cast<size_t>(image.width_px) * kBytesPerPixel;
  std::vector<uint8_t> filtered;
  filtered.reserve((stride + 1) * image.height_px);
  const std::vector<uint8_t> zero_row(stride, 0);
  std::vector<uint8_t> candidate(stride), best(stride);
  for (int y = 0; y < image.height_px; ++y) {
    const uint8_t* row = image.rgb.data() + stride * y;
    const uint8_t* up = y > 0 ? row - stride : zero_row.data();
    long best_cost = -1;
    uint8_t best_type = 0;
    for (uint8_t type = 0; type <= 4; ++type) {
      long cost = 0;
      for (size_t i = 0; i < stride; ++i) {
        const int a = i >= kBytesPerPixel ? row[i - kBytesPerPixel] : 0;
        const int b = up[i];
        const int c = i >= kBytesPerPixel ? up[i - kBytesPerPixel] : 0;
        const int predictor = type == 0 ? 0 : type == 1 ? a : type == 2 ? b
                            : type == 3 ? (a + b) / 2 : paeth(a, b, c);
        candidate[i] = static_cast<uint8_t>(row[i] - predictor);
        cost += std::abs(static_cast<int>(static_cast<int8_t>(candidate[i])));
      }
      if (best_cost < 0 || cost < best_cost) {
        best_cost = cost;
        best_type = type;
        best.swap(candidate);
      }
    }
    filtered.push_back(best_type);
    filtered.insert(filtered.end(), best.begin(), best.end());
  }
  return filtered;
}

}  // namespace

std::vector<uint8_t> encode_png(const RgbImage& image) {
  if (image.width_px <= 0 || image.height_px <= 0 ||
      image.rgb.size() != static_cast<size_t>(image.width_px) * image.height_px * kBytesPerPixel) {
    throw Error("scene generator: PNG encoder got an image of " + std::to_string(image.width_px) +
                "x" + std::to_string(image.height_px) + " px with " +
                std::to_string(image.rgb.size()) + " bytes");
  }
  const std::vector<uint8_t> scanlines = filter_rows(image);
  std::vector<uint8_t> zlib = {0x78, 0x01};  // deflate, 32 KiB window, no dictionary
  deflate_fixed(scanlines, zlib);
  put_u32_be(zlib, adler32(scanlines));

  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<uint8_t> header;
  put_u32_be(header, static_cast<uint32_t>(image.width_px));
  put_u32_be(header, static_cast<uint32_t>(image.height_px));
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8-bit truecolour, deflate, adaptive, no interlace
  put_chunk(png, "IHDR", header);
  put_chunk(png, "IDAT", zlib);
  put_chunk(png, "IEND", {});
  return png;
}

}  // namespace ontile::gen
