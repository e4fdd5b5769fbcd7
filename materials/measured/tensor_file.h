// The `tensor_file` container of the RGL material database (Dupuy & Jakob 2018; docs/references.md,
// "RGL measured BRDFs"): named n-dimensional arrays in one little-endian file.
//
//   12 bytes "tensor_file\0", 2 bytes version (1, 0), uint32 field count, then per field:
//   uint16 name length, the name, uint16 ndim, uint8 dtype, uint64 byte offset of the data
//   from the start of the file, ndim x uint64 shape. The data of each field is stored
//   row-major (last index fastest), little-endian, at its offset.
//
// The reader validates the container completely before anything uses it: the magic and the
// version, every header inside the file, names (non-empty, printable, unique), dtypes (1..11),
// shapes (the product and its byte size without overflow), data inside the file and after the
// headers, and floating-point data finite. What a field MEANS (which fields an RGL BRDF needs,
// their shapes) is the RGL model's business (rgl_brdf.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace scatterlab {

// A file that is not a valid tensor file, or cannot be read or written. The message names the
// file, the field when one is at fault, and what is allowed.
class TensorFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class TensorDtype : uint8_t {
  UInt8 = 1,
  Int8 = 2,
  UInt16 = 3,
  Int16 = 4,
  UInt32 = 5,
  Int32 = 6,
  UInt64 = 7,
  Int64 = 8,
  Float16 = 9,
  Float32 = 10,
  Float64 = 11,
};

size_t dtypeBytes(TensorDtype dtype);
std::string toString(TensorDtype dtype);  // "float32", ...
bool isFloatingPoint(TensorDtype dtype);

struct TensorField {
  std::string name;
  TensorDtype dtype = TensorDtype::Float32;
  std::vector<uint64_t> shape;
  std::vector<std::byte> data;  // row-major, little-endian, as stored

  uint64_t elementCount() const;
  // Every element converted to double (float16 and the integer types too).
  std::vector<double> values() const;
  // "float32 (8, 128)".
  std::string describe() const;

  // A field holding `values` stored as `dtype` (float32 rounds, integers must be exact);
  // values.size() must be the product of `shape`.
  static TensorField fromValues(std::string name, TensorDtype dtype, std::vector<uint64_t> shape,
                                std::span<const double> values);
  static TensorField fromText(std::string name, const std::string& text);  // uint8 (n)
};

class TensorFile {
 public:
  // Fields in file order.
  const std::vector<TensorField>& fields() const { return fields_; }
  const TensorField* find(const std::string& name) const;
  // Adds a field, or replaces the field of the same name in place.
  void set(TensorField field);
  bool remove(const std::string& name);

 private:
  std::vector<TensorField> fields_;
};

// Parses the bytes of a tensor file; `source` names it in errors ("tensor file \"x.bsdf\"").
TensorFile parseTensorFile(std::span<const std::byte> bytes, const std::string& source);
// Reads and parses a file; throws TensorFileError naming the path.
TensorFile readTensorFile(const std::filesystem::path& path);

// The bytes of a tensor file: headers in field order, then each field's data aligned to 8 bytes.
std::vector<std::byte> serializeTensorFile(const TensorFile& file);
// Writes atomically (temporary name, then rename): a failure leaves no file behind.
void writeTensorFile(const std::filesystem::path& path, const TensorFile& file);

// True when `bytes` start with the tensor_file magic (format detection by content).
bool hasTensorFileMagic(std::span<const std::byte> bytes);
// True when the file at `path` can be opened and starts with the magic.
bool isTensorFile(const std::filesystem::path& path);

}  // namespace scatterlab
