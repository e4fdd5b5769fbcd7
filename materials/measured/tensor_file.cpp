#include "materials/measured/tensor_file.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>

#include "materials/core/atomic_file.h"

namespace scatterlab {

namespace {

namespace fs = std::filesystem;

constexpr std::array<char, 12> Magic{'t', 'e', 'n', 's', 'o', 'r', '_', 'f', 'i', 'l', 'e', '\0'};
constexpr size_t PreambleBytes = Magic.size() + 2 + 4;  // magic, version, field count
// A field header without its name and shape: name length, ndim, dtype, offset.
constexpr size_t FieldHeaderBytes = 2 + 2 + 1 + 8;
// More dimensions than any array needs; bounds the shape read from a corrupt header.
constexpr uint16_t MaxDimensions = 32;

const char* const DtypeNames[] = {"invalid", "uint8",  "int8",  "uint16",  "int16",   "uint32",
                                  "int32",   "uint64", "int64", "float16", "float32", "float64"};

// The unsigned word as wide as T (integers and IEEE floats alike).
template <size_t Bytes> struct WordOf;
template <> struct WordOf<1> { using type = uint8_t; };
template <> struct WordOf<2> { using type = uint16_t; };
template <> struct WordOf<4> { using type = uint32_t; };
template <> struct WordOf<8> { using type = uint64_t; };
template <typename T> using Word = typename WordOf<sizeof(T)>::type;

// Little-endian words, independent of the host's byte order.
template <typename T> T loadLittleEndian(const std::byte* p) {
  Word<T> word = 0;
  for (size_t i = 0; i < sizeof(T); ++i) word = Word<T>(word | (Word<T>(uint8_t(p[i])) << (8 * i)));
  T value;  // memcpy, not std::bit_cast: Emscripten 3.1's libc++ (the explorer's build) lacks it
  std::memcpy(&value, &word, sizeof(T));
  return value;
}

template <typename T> void storeLittleEndian(std::byte* p, T value) {
  Word<T> word;
  std::memcpy(&word, &value, sizeof(T));
  for (size_t i = 0; i < sizeof(T); ++i) p[i] = std::byte((word >> (8 * i)) & 0xff);
}

// IEEE 754 binary16 -> double.
double halfToDouble(uint16_t bits) {
  const int exponent = (bits >> 10) & 0x1f;
  const int mantissa = bits & 0x3ff;
  const double sign = (bits & 0x8000) ? -1.0 : 1.0;
  if (exponent == 0) return sign * std::ldexp(double(mantissa), -24);
  if (exponent == 31)
    return mantissa ? std::numeric_limits<double>::quiet_NaN()
                    : sign * std::numeric_limits<double>::infinity();
  return sign * std::ldexp(double(mantissa | 0x400), exponent - 25);
}

// double -> binary16, rounded to nearest even; |value| must be below 65520 (the largest half
// rounds from there on to infinity).
uint16_t doubleToHalf(double value) {
  const uint16_t sign = std::signbit(value) ? 0x8000 : 0;
  const double a = std::abs(value);
  if (!(a < 65520.0)) throw std::invalid_argument("value " + std::to_string(value) + " does not fit float16");
  int e = 0;
  std::frexp(a, &e);  // a = m 2^e, m in [0.5, 1)
  if (a == 0.0 || e - 1 < -14) return uint16_t(sign | uint16_t(std::nearbyint(std::ldexp(a, 24))));
  const auto mantissa = uint32_t(std::nearbyint(std::ldexp(a, 11 - e)));   // in [1024, 2048]
  const uint32_t bits = (uint32_t(e - 1 + 15) << 10) + (mantissa - 1024);  // a carry lands in the exponent
  return uint16_t(sign | bits);
}

double elementValue(TensorDtype dtype, const std::byte* p) {
  switch (dtype) {
    case TensorDtype::UInt8: return double(uint8_t(p[0]));
    case TensorDtype::Int8: return double(int8_t(uint8_t(p[0])));
    case TensorDtype::UInt16: return double(loadLittleEndian<uint16_t>(p));
    case TensorDtype::Int16: return double(loadLittleEndian<int16_t>(p));
    case TensorDtype::UInt32: return double(loadLittleEndian<uint32_t>(p));
    case TensorDtype::Int32: return double(loadLittleEndian<int32_t>(p));
    case TensorDtype::UInt64: return double(loadLittleEndian<uint64_t>(p));
    case TensorDtype::Int64: return double(loadLittleEndian<int64_t>(p));
    case TensorDtype::Float16: return halfToDouble(loadLittleEndian<uint16_t>(p));
    case TensorDtype::Float32: return double(loadLittleEndian<float>(p));
    case TensorDtype::Float64: return loadLittleEndian<double>(p);
  }
  throw std::logic_error("tensor field with an invalid dtype");
}

template <typename T> void storeInteger(std::byte* p, double value, const std::string& name) {
  if (!(value == std::nearbyint(value)) || value < double(std::numeric_limits<T>::lowest()) ||
      value > double(std::numeric_limits<T>::max()))
    throw std::invalid_argument("tensor field \"" + name + "\": " + std::to_string(value) +
                                " is not an integer its dtype can hold");
  storeLittleEndian<T>(p, T(value));
}

void storeElement(TensorDtype dtype, std::byte* p, double value, const std::string& name) {
  switch (dtype) {
    case TensorDtype::UInt8: return storeInteger<uint8_t>(p, value, name);
    case TensorDtype::Int8: return storeInteger<int8_t>(p, value, name);
    case TensorDtype::UInt16: return storeInteger<uint16_t>(p, value, name);
    case TensorDtype::Int16: return storeInteger<int16_t>(p, value, name);
    case TensorDtype::UInt32: return storeInteger<uint32_t>(p, value, name);
    case TensorDtype::Int32: return storeInteger<int32_t>(p, value, name);
    case TensorDtype::UInt64: return storeInteger<uint64_t>(p, value, name);
    case TensorDtype::Int64: return storeInteger<int64_t>(p, value, name);
    case TensorDtype::Float16: return storeLittleEndian<uint16_t>(p, doubleToHalf(value));
    case TensorDtype::Float32: return storeLittleEndian<float>(p, float(value));
    case TensorDtype::Float64: return storeLittleEndian<double>(p, value);
  }
  throw std::logic_error("tensor field with an invalid dtype");
}

std::string shapeText(const std::vector<uint64_t>& shape) {
  std::string text = "(";
  for (size_t i = 0; i < shape.size(); ++i) text += (i ? ", " : "") + std::to_string(shape[i]);
  return text + ")";
}

// Reads the headers and data of a tensor file held in memory, failing with the source's name.
class Parser {
 public:
  Parser(std::span<const std::byte> bytes, std::string source) : bytes_(bytes), source_(std::move(source)) {}

  TensorFile parse() {
    if (bytes_.size() < PreambleBytes)
      fail("truncated: " + std::to_string(bytes_.size()) + " bytes, shorter than the " +
           std::to_string(PreambleBytes) + "-byte preamble (\"tensor_file\\0\", version, field count)");
    if (!hasTensorFileMagic(bytes_)) fail("bad header: the file does not start with \"tensor_file\\0\"");
    const auto major = uint8_t(bytes_[12]), minor = uint8_t(bytes_[13]);
    if (major != 1 || minor != 0)
      fail("unsupported version " + std::to_string(major) + "." + std::to_string(minor) + "; allowed: 1.0");
    const uint32_t count = loadLittleEndian<uint32_t>(&bytes_[14]);
    position_ = PreambleBytes;
    // Each field header takes at least FieldHeaderBytes + 1 (a name is not empty).
    if (uint64_t(count) * (FieldHeaderBytes + 1) > bytes_.size() - position_)
      fail("truncated: " + std::to_string(count) + " fields announced, but only " +
           std::to_string(bytes_.size() - position_) + " bytes follow the preamble");

    struct Header {
      TensorField field;
      uint64_t offset = 0, byteCount = 0;
    };
    std::vector<Header> headers;
    std::set<std::string> names;
    for (uint32_t i = 0; i < count; ++i) {
      const std::string where = "field #" + std::to_string(i + 1) + " of " + std::to_string(count);
      Header h;
      const uint16_t nameLength = read<uint16_t>(where + ": name length");
      if (nameLength == 0) fail(where + ": empty name; allowed: 1 or more printable ASCII characters");
      need(nameLength, where + ": name");
      h.field.name.assign(reinterpret_cast<const char*>(&bytes_[position_]), nameLength);
      position_ += nameLength;
      for (char c : h.field.name)
        if (c < 0x20 || c > 0x7e)
          fail(where + ": name with a non-printable byte " + std::to_string(int(uint8_t(c))) +
               "; allowed: printable ASCII");
      const std::string fieldName = "field \"" + h.field.name + "\"";
      if (!names.insert(h.field.name).second) fail(fieldName + ": appears twice; allowed: unique names");
      const uint16_t ndim = read<uint16_t>(fieldName + ": ndim");
      const uint8_t dtype = read<uint8_t>(fieldName + ": dtype");
      if (dtype < 1 || dtype > 11)
        fail(
            fieldName + ": unknown dtype " + std::to_string(dtype) +
            "; allowed: 1 to 11 (uint8, int8, uint16, int16, uint32, int32, uint64, int64, float16, float32, "
            "float64)");
      h.field.dtype = TensorDtype(dtype);
      h.offset = read<uint64_t>(fieldName + ": offset");
      if (ndim > MaxDimensions)
        fail(fieldName + ": " + std::to_string(ndim) + " dimensions; allowed: at most " +
             std::to_string(MaxDimensions));
      uint64_t elements = 1;
      for (uint16_t d = 0; d < ndim; ++d) {
        const uint64_t extent = read<uint64_t>(fieldName + ": shape");
        h.field.shape.push_back(extent);
        if (extent != 0 && elements > std::numeric_limits<uint64_t>::max() / extent)
          fail(fieldName + ": shape " + shapeText(h.field.shape) + "... overflows 64 bits");
        elements *= extent;
      }
      const uint64_t elementBytes = dtypeBytes(h.field.dtype);
      if (elements > std::numeric_limits<uint64_t>::max() / elementBytes)
        fail(fieldName + ": shape " + shapeText(h.field.shape) + " overflows 64 bits");
      h.byteCount = elements * elementBytes;
      headers.push_back(std::move(h));
    }

    const uint64_t headerEnd = position_;
    TensorFile file;
    for (Header& h : headers) {
      const std::string fieldName = "field \"" + h.field.name + "\" (" + h.field.describe() + ")";
      if (h.offset < headerEnd && h.byteCount > 0)
        fail(fieldName + ": data offset " + std::to_string(h.offset) +
             " lies inside the headers (which end at " + std::to_string(headerEnd) + ")");
      if (h.offset > bytes_.size() || h.byteCount > bytes_.size() - h.offset)
        fail(fieldName + ": data at offset " + std::to_string(h.offset) + ", " + std::to_string(h.byteCount) +
             " bytes, runs past the end of the file (" + std::to_string(bytes_.size()) +
             " bytes; truncated?)");
      const auto first = bytes_.begin() + std::ptrdiff_t(h.offset);
      h.field.data.assign(first, first + std::ptrdiff_t(h.byteCount));
      if (isFloatingPoint(h.field.dtype)) checkFinite(h.field, fieldName);
      file.set(std::move(h.field));
    }
    return file;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw TensorFileError(source_ + ": " + problem);
  }

  void need(uint64_t count, const std::string& what) const {
    if (count > bytes_.size() - position_)
      fail("truncated in the headers: " + what + " needs " + std::to_string(count) + " bytes at offset " +
           std::to_string(position_) + ", the file has " + std::to_string(bytes_.size()));
  }

  template <typename T> T read(const std::string& what) {
    need(sizeof(T), what);
    const T value = loadLittleEndian<T>(&bytes_[position_]);
    position_ += sizeof(T);
    return value;
  }

  void checkFinite(const TensorField& field, const std::string& fieldName) const {
    const size_t size = dtypeBytes(field.dtype);
    const uint64_t n = field.elementCount();
    uint64_t bad = 0, first = 0;
    for (uint64_t i = 0; i < n; ++i)
      if (!std::isfinite(elementValue(field.dtype, &field.data[i * size])) && bad++ == 0) first = i;
    if (bad > 0)
      fail(fieldName + ": " + std::to_string(bad) +
           " value(s) are NaN or infinite, the first at flat index " + std::to_string(first) +
           "; allowed: finite numbers");
  }

  std::span<const std::byte> bytes_;
  std::string source_;
  uint64_t position_ = 0;
};

}  // namespace

size_t dtypeBytes(TensorDtype dtype) {
  switch (dtype) {
    case TensorDtype::UInt8:
    case TensorDtype::Int8: return 1;
    case TensorDtype::UInt16:
    case TensorDtype::Int16:
    case TensorDtype::Float16: return 2;
    case TensorDtype::UInt32:
    case TensorDtype::Int32:
    case TensorDtype::Float32: return 4;
    case TensorDtype::UInt64:
    case TensorDtype::Int64:
    case TensorDtype::Float64: return 8;
  }
  throw std::logic_error("invalid tensor dtype");
}

std::string toString(TensorDtype dtype) {
  const auto index = size_t(dtype);
  return index >= 1 && index <= 11 ? DtypeNames[index] : "invalid";
}

bool isFloatingPoint(TensorDtype dtype) {
  return dtype == TensorDtype::Float16 || dtype == TensorDtype::Float32 || dtype == TensorDtype::Float64;
}

uint64_t TensorField::elementCount() const {
  uint64_t n = 1;
  for (uint64_t extent : shape) n *= extent;
  return n;
}

std::vector<double> TensorField::values() const {
  const size_t size = dtypeBytes(dtype);
  std::vector<double> out(data.size() / size);
  for (size_t i = 0; i < out.size(); ++i) out[i] = elementValue(dtype, &data[i * size]);
  return out;
}

std::string TensorField::describe() const { return toString(dtype) + " " + shapeText(shape); }

TensorField TensorField::fromValues(std::string name, TensorDtype dtype, std::vector<uint64_t> shape,
                                    std::span<const double> values) {
  TensorField field{std::move(name), dtype, std::move(shape), {}};
  if (field.elementCount() != values.size())
    throw std::invalid_argument("tensor field \"" + field.name + "\": " + std::to_string(values.size()) +
                                " values for shape " + shapeText(field.shape));
  const size_t size = dtypeBytes(dtype);
  field.data.resize(values.size() * size);
  for (size_t i = 0; i < values.size(); ++i)
    storeElement(dtype, &field.data[i * size], values[i], field.name);
  return field;
}

TensorField TensorField::fromText(std::string name, const std::string& text) {
  TensorField field{std::move(name), TensorDtype::UInt8, {text.size()}, {}};
  for (char c : text) field.data.push_back(std::byte(uint8_t(c)));
  return field;
}

const TensorField* TensorFile::find(const std::string& name) const {
  const auto it =
      std::find_if(fields_.begin(), fields_.end(), [&](const TensorField& f) { return f.name == name; });
  return it == fields_.end() ? nullptr : &*it;
}

void TensorFile::set(TensorField field) {
  for (TensorField& existing : fields_)
    if (existing.name == field.name) {
      existing = std::move(field);
      return;
    }
  fields_.push_back(std::move(field));
}

bool TensorFile::remove(const std::string& name) {
  return std::erase_if(fields_, [&](const TensorField& f) { return f.name == name; }) > 0;
}

bool hasTensorFileMagic(std::span<const std::byte> bytes) {
  return bytes.size() >= Magic.size() && std::memcmp(bytes.data(), Magic.data(), Magic.size()) == 0;
}

bool isTensorFile(const fs::path& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return false;
  std::ifstream in(path, std::ios::binary);
  std::array<std::byte, Magic.size()> head{};
  return in.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size())) &&
         hasTensorFileMagic(head);
}

TensorFile parseTensorFile(std::span<const std::byte> bytes, const std::string& source) {
  return Parser(bytes, source).parse();
}

TensorFile readTensorFile(const fs::path& path) {
  const std::string source = "tensor file \"" + path.string() + "\"";
  std::error_code error;
  const auto status = fs::status(path, error);
  if (!fs::exists(status)) throw TensorFileError(source + ": not found");
  if (fs::is_directory(status)) throw TensorFileError(source + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TensorFileError(source + ": not readable (" + std::strerror(errno) + ")");
  const uintmax_t size = fs::file_size(path, error);
  if (error) throw TensorFileError(source + ": not readable (" + error.message() + ")");
  std::vector<std::byte> bytes(size);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
    throw TensorFileError(source + ": read failed after " + std::to_string(in.gcount()) + " of " +
                          std::to_string(size) + " bytes");
  return parseTensorFile(bytes, source);
}

std::vector<std::byte> serializeTensorFile(const TensorFile& file) {
  size_t headerBytes = PreambleBytes;
  for (const TensorField& field : file.fields())
    headerBytes += FieldHeaderBytes + field.name.size() + 8 * field.shape.size();
  const auto align = [](size_t offset) { return (offset + 7) / 8 * 8; };
  std::vector<size_t> offsets;
  size_t end = align(headerBytes);
  for (const TensorField& field : file.fields()) {
    offsets.push_back(end);
    end = align(end + field.data.size());
  }
  std::vector<std::byte> bytes(end, std::byte{0});
  std::memcpy(bytes.data(), Magic.data(), Magic.size());
  bytes[12] = std::byte{1};
  bytes[13] = std::byte{0};
  storeLittleEndian<uint32_t>(&bytes[14], uint32_t(file.fields().size()));
  size_t p = PreambleBytes;
  for (size_t i = 0; i < file.fields().size(); ++i) {
    const TensorField& field = file.fields()[i];
    storeLittleEndian<uint16_t>(&bytes[p], uint16_t(field.name.size()));
    std::memcpy(&bytes[p + 2], field.name.data(), field.name.size());
    p += 2 + field.name.size();
    storeLittleEndian<uint16_t>(&bytes[p], uint16_t(field.shape.size()));
    bytes[p + 2] = std::byte(uint8_t(field.dtype));
    storeLittleEndian<uint64_t>(&bytes[p + 3], uint64_t(offsets[i]));
    p += FieldHeaderBytes - 2;
    for (uint64_t extent : field.shape) {
      storeLittleEndian<uint64_t>(&bytes[p], extent);
      p += 8;
    }
    std::copy(field.data.begin(), field.data.end(), bytes.begin() + std::ptrdiff_t(offsets[i]));
  }
  return bytes;
}

void writeTensorFile(const fs::path& path, const TensorFile& file) {
  const std::string target = "tensor file \"" + path.string() + "\"";
  for (const TensorField& field : file.fields()) {
    if (field.name.empty() || field.name.size() > std::numeric_limits<uint16_t>::max() ||
        field.shape.size() > MaxDimensions ||
        field.data.size() != field.elementCount() * dtypeBytes(field.dtype))
      throw TensorFileError(target + ": not written: field \"" + field.name + "\" (" + field.describe() +
                            ") is malformed (name length, dimensions, or data size)");
  }
  const std::vector<std::byte> bytes = serializeTensorFile(file);
  std::error_code error;
  const fs::path directory = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  if (!fs::is_directory(directory, error))
    throw TensorFileError(target + ": not written: directory \"" + directory.string() + "\" does not exist");
  try {
    writeFileAtomically(path, [&](const fs::path& temporary) {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out)
        throw TensorFileError(target + ": not written: cannot create a file (" + std::strerror(errno) + ")");
      out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
      out.close();
      if (!out) throw TensorFileError(target + ": not written: write failed (" + std::strerror(errno) + ")");
    });
  } catch (const fs::filesystem_error& e) {
    throw TensorFileError(target + ": not written: " + e.code().message());
  }
}

}  // namespace scatterlab
