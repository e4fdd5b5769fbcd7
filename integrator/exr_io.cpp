#include "integrator/exr_io.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <system_error>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>

#include "integrator/render_error.h"
#include "materials/core/atomic_file.h"
#include "materials/core/quoted.h"

namespace scatterlab {

namespace {

std::string channelName(const ExrLayer& layer, int c) {
  return layer.prefix.empty() ? layer.channelNames[c] : layer.prefix + "." + layer.channelNames[c];
}

}  // namespace

void writeExr(const std::filesystem::path& path, const std::vector<ExrLayer>& layers) {
  if (layers.empty() || !layers.front().image) throw std::invalid_argument("writeExr: no layers");
  const int width = layers.front().image->width(), height = layers.front().image->height();
  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  Imf::FrameBuffer frameBuffer;
  for (const ExrLayer& layer : layers) {
    const Image& image = *layer.image;
    if (image.width() != width || image.height() != height || image.channels() != 3)
      throw std::invalid_argument("writeExr: layers must be 3-channel images of one size");
    for (int c = 0; c < 3; ++c) {
      const std::string name = channelName(layer, c);
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      // Slices point into const data: OutputFile only reads them.
      char* base = reinterpret_cast<char*>(const_cast<float*>(image.data().data() + c));
      frameBuffer.insert(name,
                         Imf::Slice(Imf::FLOAT, base, sizeof(float) * 3, sizeof(float) * 3 * size_t(width)));
    }
  }
  try {
    writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
      // The stream is ours, so that its close is checked: OpenEXR writes through a buffered
      // std::ofstream whose last bytes reach the disk in a destructor that cannot report a
      // full disk or a file-size limit, which would leave a truncated file and no error.
      std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
      if (!stream)
        throw std::runtime_error(std::string("cannot create the file (") + std::strerror(errno) + ")");
      {
        Imf::StdOFStream out(stream, temporary.c_str());
        Imf::OutputFile file(out, header);
        file.setFrameBuffer(frameBuffer);
        file.writePixels(height);
      }
      stream.close();
      if (!stream) throw std::runtime_error(std::string("write failed (") + std::strerror(errno) + ")");
    });
  } catch (const std::exception& error) {
    throw RenderInputError("cannot write " + inQuotes(path.string()) + ": " + error.what() +
                           "; allowed: a writable path in an existing directory");
  }
}

namespace {

// Throws unless `path` names an existing file.
void checkReadable(const std::filesystem::path& path, const std::string& name) {
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw RenderInputError(name + ": no such file; allowed: an OpenEXR file");
  if (std::filesystem::is_directory(path, error))
    throw RenderInputError(name + ": is a directory; allowed: an OpenEXR file");
}

// The data window's size, against the limits of readExrRgb (exr_io.h).
void checkDataWindow(const std::string& name, long width, long height, long maxPixels) {
  constexpr long MaxSide = 1 << 16;
  if (width < 1 || height < 1 || width > MaxSide || height > MaxSide || width * height > maxPixels)
    throw RenderInputError(name + ": data window of " + std::to_string(width) + " x " +
                           std::to_string(height) + " pixels; allowed: 1 to " + std::to_string(MaxSide) +
                           " pixels per side and at most " + std::to_string(maxPixels) + " pixels" +
                           (maxPixels == MaxExrPixels ? " (8192 x 4096)" : "") +
                           ", checked before the pixels are read");
}

int32_t littleEndian32(const unsigned char* bytes) {
  return int32_t(uint32_t(bytes[0]) | uint32_t(bytes[1]) << 8 | uint32_t(bytes[2]) << 16 |
                 uint32_t(bytes[3]) << 24);
}

// The value size of each attribute type whose value OpenEXR reads by its layout, whatever size
// the file declares (the readValueFrom of OpenEXR's Imf*Attribute.cpp, and the types of the file
// format's documentation). Strings, string and float vectors, previews and unknown types are read
// at their declared size instead; a channel list is read up to its end marker.
std::optional<uint64_t> fixedValueSize(const std::string& type) {
  // clang-format off
  static const std::map<std::string, uint64_t, std::less<>> sizes = {
      {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"deepImageState", 1},
      {"double", 8}, {"envmap", 1}, {"float", 4}, {"int", 4}, {"keycode", 28}, {"lineOrder", 1},
      {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"rational", 8}, {"tiledesc", 9},
      {"timecode", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12}, {"v3d", 24}};
  // clang-format on
  const auto found = sizes.find(type);
  return found == sizes.end() ? std::nullopt : std::optional<uint64_t>(found->second);
}

// OpenEXR allocates (and zeroes) each header attribute's value at the size the file declares
// before it reads it, so a few bytes declaring a 2 GB attribute cost 2 GB. The attributes are
// walked here first, as OpenEXR's Header::readFrom reads them (the file layout: a 4-byte magic
// number, a 4-byte version whose bit 12 marks a multi-part file; then per part the attributes
// "name\0type\0", each text at most 255 bytes, a 4-byte little-endian size and the value; a header
// ends in an empty name, and a multi-part file's list of headers in an empty header), and a size
// beyond the bytes left in the file is refused. So that this walk and OpenEXR's stay in step, a
// value OpenEXR reads by its layout must be the size it declares: a fixed-size type's size
// (fixedValueSize) and a channel list's entries ("name\0" and 16 bytes each, then a 0). OpenEXR
// also sizes buffers from the data window as it opens the file, so a "dataWindow" attribute is
// checked here too (with `maxPixels`; none: no pixel limit, as for readExrChannelNames). What
// OpenEXR itself refuses (no magic number, a text without its 0) is left to it.
void checkHeader(const std::filesystem::path& path, const std::string& name, std::optional<long> maxPixels) {
  std::ifstream in(path, std::ios::binary);
  std::error_code error;
  const auto fileSize = std::filesystem::file_size(path, error);
  unsigned char start[8];
  if (error || !in.read(reinterpret_cast<char*>(start), 8)) return;
  if (!(start[0] == 0x76 && start[1] == 0x2f && start[2] == 0x31 && start[3] == 0x01)) return;
  const bool multiPart = (start[5] & 0x10) != 0;
  constexpr size_t MaxText = 255;  // OpenEXR's Name::MAX_LENGTH
  const auto readText = [&](std::string& text) {
    text.clear();
    for (char c; in.get(c);) {
      if (c == '\0') return true;
      if (text.size() == MaxText) return false;
      text.push_back(c);
    }
    return false;
  };
  for (bool firstInPart = true;;) {
    std::string attribute, type;
    if (!readText(attribute)) return;
    if (attribute.empty()) {
      // The end of a header: of the file's only one, or, in a multi-part file, the end of the
      // list when the header was empty.
      if (!multiPart || firstInPart) return;
      firstInPart = true;
      continue;
    }
    firstInPart = false;
    unsigned char size[4];
    if (!readText(type) || !in.read(reinterpret_cast<char*>(size), 4)) return;
    const uint64_t declared = uint32_t(littleEndian32(size));
    const uint64_t at = uint64_t(in.tellg());
    const std::string what = name + ": header attribute \"" + attribute + "\" (" + type + ") declares " +
                             std::to_string(littleEndian32(size)) + " bytes";
    if (declared > fileSize - std::min<uint64_t>(at, fileSize))
      throw RenderInputError(what + ", but " + std::to_string(fileSize - at) +
                             " are left in the file; allowed: an OpenEXR file whose attributes fit in it");
    if (const auto fixed = fixedValueSize(type); fixed && declared != *fixed)
      throw RenderInputError(what + "; allowed: " + std::to_string(*fixed) + ", the size of a " + type +
                             " value");
    if (type == "chlist") {
      std::string channel;
      while (readText(channel) && !channel.empty()) in.seekg(16, std::ios::cur);
      const uint64_t used = uint64_t(in.tellg());
      if (!in || used - at != declared)
        throw RenderInputError(what + ", but its channel list takes " +
                               (in ? std::to_string(used - at) : std::string("more than the file")) +
                               "; allowed: a channel list of the size it declares");
      continue;
    }
    unsigned char box[16];
    if (maxPixels && attribute == "dataWindow" && type == "box2i" &&
        in.read(reinterpret_cast<char*>(box), 16)) {
      // xMin, yMin, xMax, yMax
      checkDataWindow(name, long(littleEndian32(box + 8)) - littleEndian32(box) + 1,
                      long(littleEndian32(box + 12)) - littleEndian32(box + 4) + 1, *maxPixels);
      continue;
    }
    in.seekg(std::streamoff(declared), std::ios::cur);
  }
}

}  // namespace

std::vector<std::string> readExrChannelNames(const std::filesystem::path& path) {
  const std::string name = "EXR file " + inQuotes(path.string());
  checkReadable(path, name);
  checkHeader(path, name, std::nullopt);
  try {
    const Imf::InputFile file(path.c_str());
    std::vector<std::string> names;
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
      names.push_back(it.name());
    return names;
  } catch (const std::exception& error) {
    throw RenderInputError(name + ": cannot be read as OpenEXR (" + error.what() +
                           "); allowed: an OpenEXR file");
  }
}

Image readExrRgb(const std::filesystem::path& path, const std::string& what, long maxPixels) {
  const std::string name = what + " " + inQuotes(path.string());
  checkReadable(path, name);
  maxPixels = std::min(maxPixels, MaxExrPixels);
  checkHeader(path, name, maxPixels);
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const long width = long(window.max.x) - window.min.x + 1, height = long(window.max.y) - window.min.y + 1;
    checkDataWindow(name, width, height, maxPixels);
    const Imf::ChannelList& channels = file.header().channels();
    const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    const bool grey = !rgb && channels.findChannel("Y");
    if (!rgb && !grey) {
      std::string found;
      for (auto it = channels.begin(); it != channels.end(); ++it)
        found += std::string(found.empty() ? "" : ", ") + it.name();
      throw RenderInputError(name + ": has channels [" + found +
                             "]; allowed: an image with R, G and B (or Y) channels");
    }
    Image image(int(width), int(height), 3);
    Imf::FrameBuffer frameBuffer;
    for (int c = 0; c < 3; ++c) {
      // Slice::Make places the first pixel of the data window at the given address.
      frameBuffer.insert(grey ? "Y" : std::string(1, "RGB"[c]),
                         Imf::Slice::Make(Imf::FLOAT, image.data().data() + c, window, sizeof(float) * 3,
                                          sizeof(float) * 3 * size_t(width)));
      if (grey) break;
    }
    file.setFrameBuffer(frameBuffer);
    file.readPixels(window.min.y, window.max.y);
    if (grey)
      for (size_t i = 0; i < image.data().size(); i += 3)
        image.data()[i + 1] = image.data()[i + 2] = image.data()[i];
    return image;
  } catch (const RenderInputError&) {
    throw;
  } catch (const std::exception& error) {
    throw RenderInputError(name + ": cannot be read as OpenEXR (" + error.what() +
                           "); allowed: an OpenEXR file");
  }
}

}  // namespace scatterlab
