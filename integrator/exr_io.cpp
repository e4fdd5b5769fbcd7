#include "integrator/exr_io.h"

#include <cerrno>
#include <cstring>
#include <fstream>
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

}  // namespace

std::vector<std::string> readExrChannelNames(const std::filesystem::path& path) {
  const std::string name = "EXR file " + inQuotes(path.string());
  checkReadable(path, name);
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

Image readExrRgb(const std::filesystem::path& path, const std::string& what) {
  const std::string name = what + " " + inQuotes(path.string());
  checkReadable(path, name);
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const long width = long(window.max.x) - window.min.x + 1, height = long(window.max.y) - window.min.y + 1;
    constexpr long MaxSide = 1 << 16;
    if (width < 1 || height < 1 || width > MaxSide || height > MaxSide || width * height > MaxExrPixels)
      throw RenderInputError(name + ": data window of " + std::to_string(width) + " x " +
                             std::to_string(height) + " pixels; allowed: 1 to " + std::to_string(MaxSide) +
                             " pixels per side and at most " + std::to_string(MaxExrPixels) +
                             " pixels (8192 x 4096), checked before the pixels are read");
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
