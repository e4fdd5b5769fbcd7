// The tensor_file container (docs/references.md, "RGL measured BRDFs"): the layout read from bytes
// written by hand, write -> read round trips for every dtype, and one clear error for each kind
// of corrupt file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "materials/measured/tensor_file.h"
#include "measured_test_support.h"

namespace scatterlab {
namespace tensor_file_test {

namespace fs = std::filesystem;
using measured_test::scratchPath;

// Appends little-endian words to a byte string (this machine is little-endian: checked below).
struct Bytes {
  std::string text;
  template <typename T> Bytes& put(T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    text.append(raw, sizeof(T));
    return *this;
  }
  Bytes& put(const std::string& s) {
    text += s;
    return *this;
  }
  std::span<const std::byte> span() const {
    return {reinterpret_cast<const std::byte*>(text.data()), text.size()};
  }
};

// A file of two fields, written by hand as the format describes: "a" float32 (2, 2) and "b"
// uint16 (3).
Bytes handWrittenFile() {
  Bytes b;
  b.put(std::string("tensor_file", 12)).put<uint8_t>(1).put<uint8_t>(0).put<uint32_t>(2);
  const uint64_t headerEnd = 18 + (2 + 1 + 2 + 1 + 8 + 16) + (2 + 1 + 2 + 1 + 8 + 8);
  b.put<uint16_t>(1).put(std::string("a")).put<uint16_t>(2).put<uint8_t>(10).put<uint64_t>(headerEnd);
  b.put<uint64_t>(2).put<uint64_t>(2);
  b.put<uint16_t>(1).put(std::string("b")).put<uint16_t>(1).put<uint8_t>(3).put<uint64_t>(headerEnd + 16);
  b.put<uint64_t>(3);
  for (float v : {1.5f, -2.0f, 0.25f, 1e-3f}) b.put(v);
  for (uint16_t v : {7, 65535, 0}) b.put(v);
  return b;
}

std::string parseError(std::span<const std::byte> bytes) {
  try {
    parseTensorFile(bytes, "tensor file \"test.bsdf\"");
  } catch (const TensorFileError& error) {
    return error.what();
  }
  return "";
}

void expectMentions(const std::string& message, const std::vector<std::string>& fragments) {
  EXPECT_FALSE(message.empty()) << "no error";
  for (const std::string& fragment : fragments)
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "\"" << fragment << "\" missing from: " << message;
}

TEST(TensorFile, ReadsAFileWrittenByHand) {
  static_assert(std::endian::native == std::endian::little,
                "the hand-written bytes assume a little-endian host");
  const Bytes b = handWrittenFile();
  const TensorFile file = parseTensorFile(b.span(), "hand");
  ASSERT_EQ(file.fields().size(), 2u);
  const TensorField* a = file.find("a");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->dtype, TensorDtype::Float32);
  EXPECT_EQ(a->shape, (std::vector<uint64_t>{2, 2}));
  EXPECT_EQ(a->values(), (std::vector<double>{1.5, -2.0, 0.25, double(1e-3f)}));
  EXPECT_EQ(file.find("b")->values(), (std::vector<double>{7, 65535, 0}));
  EXPECT_EQ(file.find("b")->describe(), "uint16 (3)");
  EXPECT_EQ(file.find("c"), nullptr);
}

TEST(TensorFile, RoundTripsEveryDtype) {
  TensorFile file;
  const std::vector<double> small{0, 1, 2, 100, 127, 3};
  const std::vector<double> signedValues{-128, -1, 0, 5, 127, -7};
  file.set(TensorField::fromValues("u8", TensorDtype::UInt8, {2, 3}, small));
  file.set(TensorField::fromValues("i8", TensorDtype::Int8, {6}, signedValues));
  file.set(
      TensorField::fromValues("u16", TensorDtype::UInt16, {6}, std::vector<double>{0, 1, 65535, 2, 3, 4}));
  file.set(TensorField::fromValues("i16", TensorDtype::Int16, {6},
                                   std::vector<double>{-32768, 32767, 0, 1, 2, 3}));
  file.set(
      TensorField::fromValues("u32", TensorDtype::UInt32, {1, 1, 2}, std::vector<double>{4294967295.0, 0}));
  file.set(TensorField::fromValues("i32", TensorDtype::Int32, {2}, std::vector<double>{-2147483648.0, 7}));
  file.set(
      TensorField::fromValues("u64", TensorDtype::UInt64, {2}, std::vector<double>{9007199254740992.0, 1}));
  file.set(
      TensorField::fromValues("i64", TensorDtype::Int64, {2}, std::vector<double>{-9007199254740992.0, 1}));
  // float16: exact halves, a subnormal (2^-24) and the largest finite (65504).
  file.set(TensorField::fromValues("f16", TensorDtype::Float16, {5},
                                   std::vector<double>{0.5, -1.75, std::ldexp(1.0, -24), 65504.0, 0.0}));
  file.set(TensorField::fromValues("f32", TensorDtype::Float32, {3}, std::vector<double>{0.1, -3.5, 1e30}));
  file.set(TensorField::fromValues("f64", TensorDtype::Float64, {2}, std::vector<double>{0.1, -1e-300}));
  file.set(TensorField::fromText("text", "hello"));
  file.set(TensorField::fromValues("empty", TensorDtype::Float32, {0}, std::vector<double>{}));

  const fs::path path = scratchPath("roundtrip") += ".bsdf";
  writeTensorFile(path, file);
  const TensorFile read = readTensorFile(path);
  ASSERT_EQ(read.fields().size(), file.fields().size());
  for (size_t i = 0; i < file.fields().size(); ++i) {
    const TensorField &written = file.fields()[i], &back = read.fields()[i];
    EXPECT_EQ(back.name, written.name);
    EXPECT_EQ(back.dtype, written.dtype) << written.name;
    EXPECT_EQ(back.shape, written.shape) << written.name;
    EXPECT_EQ(back.data, written.data) << written.name;
  }
  EXPECT_EQ(read.find("f16")->values(),
            (std::vector<double>{0.5, -1.75, std::ldexp(1.0, -24), 65504.0, 0.0}));
  EXPECT_EQ(read.find("f32")->values()[0], double(0.1f));
  EXPECT_EQ(read.find("f64")->values()[1], -1e-300);
  EXPECT_EQ(read.find("i8")->values(), signedValues);
  // Serialisation is deterministic: the same file gives the same bytes.
  EXPECT_EQ(serializeTensorFile(file), serializeTensorFile(read));
}

TEST(TensorFile, Float16RoundsToNearestEven) {
  // 1 + 2^-11 lies halfway between 1 and 1 + 2^-10: ties go to the even mantissa (1).
  const std::vector<double> in{1.0 + std::ldexp(1.0, -11), 1.0 + 3 * std::ldexp(1.0, -11), 2047.5, 1e-9};
  const TensorField field = TensorField::fromValues("h", TensorDtype::Float16, {4}, in);
  EXPECT_EQ(field.values(), (std::vector<double>{1.0, 1.0 + std::ldexp(1.0, -9), 2048.0, 0.0}));
  EXPECT_THROW(TensorField::fromValues("h", TensorDtype::Float16, {1}, std::vector<double>{70000.0}),
               std::invalid_argument);
  EXPECT_THROW(TensorField::fromValues("i", TensorDtype::UInt8, {1}, std::vector<double>{256.0}),
               std::invalid_argument);
  EXPECT_THROW(TensorField::fromValues("i", TensorDtype::Int16, {1}, std::vector<double>{0.5}),
               std::invalid_argument);
}

TEST(TensorFile, DetectsTheFormatByItsMagic) {
  EXPECT_TRUE(hasTensorFileMagic(handWrittenFile().span()));
  const Bytes merlLike = Bytes().put<int32_t>(90).put<int32_t>(90).put<int32_t>(180);
  EXPECT_FALSE(hasTensorFileMagic(merlLike.span()));
  EXPECT_FALSE(hasTensorFileMagic({}));
}

// ---- Bad input: one message naming the file, the field and the problem ------------------------

TEST(TensorFileErrors, TruncatedPreamble) {
  const Bytes b = handWrittenFile();
  expectMentions(parseError(b.span().first(10)), {"test.bsdf", "truncated", "10 bytes"});
}

TEST(TensorFileErrors, WrongMagic) {
  Bytes b = handWrittenFile();
  b.text[0] = 'T';
  expectMentions(parseError(b.span()), {"test.bsdf", "bad header", "tensor_file"});
}

TEST(TensorFileErrors, WrongVersion) {
  Bytes b = handWrittenFile();
  b.text[12] = 2;
  expectMentions(parseError(b.span()), {"unsupported version 2.0", "allowed: 1.0"});
}

TEST(TensorFileErrors, FieldCountBeyondTheFile) {
  Bytes b = handWrittenFile();
  const uint32_t count = 1000000;
  std::memcpy(&b.text[14], &count, 4);
  expectMentions(parseError(b.span()), {"truncated", "1000000 fields"});
}

TEST(TensorFileErrors, TruncatedInsideTheHeaders) {
  const Bytes b = handWrittenFile();
  expectMentions(parseError(b.span().first(60)), {"truncated in the headers", "field \"b\": offset"});
}

TEST(TensorFileErrors, DataPastTheEnd) {
  const Bytes b = handWrittenFile();
  expectMentions(parseError(b.span().first(b.text.size() - 1)),
                 {"field \"b\"", "uint16 (3)", "runs past the end", "truncated"});
}

TEST(TensorFileErrors, OffsetPastTheEnd) {
  Bytes b = handWrittenFile();
  const uint64_t offset = std::numeric_limits<uint64_t>::max() - 3;  // offset + size would overflow
  std::memcpy(&b.text[18 + 2 + 1 + 2 + 1], &offset, 8);
  expectMentions(parseError(b.span()), {"field \"a\"", "runs past the end"});
}

TEST(TensorFileErrors, DataInsideTheHeaders) {
  Bytes b = handWrittenFile();
  const uint64_t offset = 4;
  std::memcpy(&b.text[18 + 2 + 1 + 2 + 1], &offset, 8);
  expectMentions(parseError(b.span()), {"field \"a\"", "inside the headers"});
}

TEST(TensorFileErrors, UnknownDtype) {
  Bytes b = handWrittenFile();
  b.text[18 + 2 + 1 + 2] = 12;
  expectMentions(parseError(b.span()), {"field \"a\"", "unknown dtype 12", "allowed: 1 to 11"});
}

TEST(TensorFileErrors, ShapeOverflow) {
  Bytes b = handWrittenFile();
  const uint64_t huge = uint64_t(1) << 62;
  std::memcpy(&b.text[18 + 2 + 1 + 2 + 1 + 8], &huge, 8);
  std::memcpy(&b.text[18 + 2 + 1 + 2 + 1 + 8 + 8], &huge, 8);
  expectMentions(parseError(b.span()), {"field \"a\"", "overflows 64 bits"});
}

TEST(TensorFileErrors, DuplicateAndEmptyNames) {
  Bytes b = handWrittenFile();
  b.text[18 + 2 + 1 + 2 + 1 + 8 + 16 + 2] = 'a';  // rename "b" to "a"
  expectMentions(parseError(b.span()), {"field \"a\"", "appears twice"});
  Bytes e = handWrittenFile();
  e.text[18] = 0;  // name length 0
  expectMentions(parseError(e.span()), {"field #1", "empty name"});
}

TEST(TensorFileErrors, NonFiniteValues) {
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    Bytes b = handWrittenFile();
    const size_t dataStart = b.text.size() - 6 - 16;
    std::memcpy(&b.text[dataStart + 8], &bad, 4);
    expectMentions(parseError(b.span()), {"field \"a\"", "1 value(s) are NaN or infinite", "flat index 2"});
  }
}

TEST(TensorFileErrors, MissingFileAndDirectory) {
  expectMentions(
      [] {
        try {
          readTensorFile("/nonexistent/x.bsdf");
        } catch (const TensorFileError& e) {
          return std::string(e.what());
        }
        return std::string();
      }(),
      {"/nonexistent/x.bsdf", "not found"});
  EXPECT_THROW(readTensorFile(fs::temp_directory_path()), TensorFileError);
}

TEST(TensorFileErrors, WriteLeavesNothingBehindOnFailure) {
  TensorFile file;
  file.set(TensorField::fromValues("x", TensorDtype::Float32, {1}, std::vector<double>{1.0}));
  const fs::path missing = scratchPath("no-such-dir") / "x.bsdf";
  EXPECT_THROW(writeTensorFile(missing, file), TensorFileError);
  EXPECT_FALSE(fs::exists(missing));
}

}  // namespace tensor_file_test
}  // namespace scatterlab
