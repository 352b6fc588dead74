#pragma once
// Reads a DataArray back from a VTU file that vtu_writer.hpp wrote (inline binary, base64), for
// the tests of the writer and of what the runs write.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace abut::testing {

// Test-side decoder (RFC 4648, section 4), independent of the writer's encoder.
inline std::vector<unsigned char> base64_decode(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> bytes;
  unsigned bits = 0;
  int nbits = 0;
  for (const char c : text) {
    if (c == '=') break;
    const auto value = alphabet.find(c);
    if (value == std::string::npos) throw std::runtime_error("not base64");
    bits = (bits << 6) | static_cast<unsigned>(value);
    nbits += 6;
    if (nbits >= 8) {
      nbits -= 8;
      bytes.push_back(static_cast<unsigned char>((bits >> nbits) & 0xFFu));
    }
  }
  return bytes;
}

// The inline text of the DataArray called `name`: base64 of the UInt64 byte count (8 bytes, so
// 12 characters), then base64 of the values.
template <class T>
std::vector<T> data_array(const std::string& vtu, const std::string& name) {
  const auto tag = vtu.find("Name=\"" + name + "\"");
  if (tag == std::string::npos) throw std::runtime_error("no DataArray " + name);
  const auto begin = vtu.find('>', tag) + 1;
  const auto end = vtu.find('<', begin);
  std::string text;
  for (const char c : vtu.substr(begin, end - begin)) {
    if (!std::isspace(static_cast<unsigned char>(c))) text += c;
  }
  const auto header = base64_decode(text.substr(0, 12));
  const auto data = base64_decode(text.substr(12));
  std::uint64_t byte_count = 0;
  std::memcpy(&byte_count, header.data(), sizeof byte_count);
  EXPECT_EQ(byte_count, data.size()) << name;
  std::vector<T> values(data.size() / sizeof(T));
  std::memcpy(values.data(), data.data(), values.size() * sizeof(T));
  return values;
}

}  // namespace abut::testing
