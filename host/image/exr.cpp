#include "image/exr.h"

#include <climits>
#include <cstring>
#include <utility>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fmt/format.h>

#include "image/atomic_file.h"
#include "util/errors.h"

namespace vkp {
namespace {

constexpr const char* kChannels[3] = {"R", "G", "B"};
// A header claiming more pixels than this is corrupt or hostile; refusing it beats letting the
// allocation take the machine's memory (the limit is 16384 x 16384).
constexpr uint64_t kMaxReadPixels = uint64_t(1) << 28;

// Encodes into memory rather than straight into the file: Imf::OutputFile's destructor writes
// the line offset table and swallows any error doing so, which would let a truncated file be
// renamed into place. The memory stream cannot fail that way, and the file write that follows is
// checked byte for byte.
class MemoryOStream final : public Imf::OStream {
public:
    explicit MemoryOStream(const char* name) : Imf::OStream(name) {}

    void write(const char c[], int n) override {
        const size_t end = m_position + size_t(n);
        if (end > m_bytes.size()) m_bytes.resize(end);
        std::memcpy(m_bytes.data() + m_position, c, size_t(n));
        m_position = end;
    }
    uint64_t tellp() override { return m_position; }
    void seekp(uint64_t position) override { m_position = position; }

    std::string take() { return std::move(m_bytes); }

private:
    std::string m_bytes;
    size_t m_position = 0;
};

std::string encodeExr(const std::filesystem::path& path, const ImageRgb& image, const ExrAttributes& attributes,
                      const std::vector<ExrChannel>& extra) {
    Imf::Header header(static_cast<int>(image.width), static_cast<int>(image.height));
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* c : kChannels) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    for (const ExrChannel& c : extra) {
        if (c.values.size() != size_t(image.width) * image.height)
            throw std::runtime_error(fmt::format("channel {} has {} values for {}x{} pixels", c.name, c.values.size(),
                                                 image.width, image.height));
        header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
    }
    for (const auto& [key, value] : attributes) header.insert(key, Imf::StringAttribute(value));

    Imf::FrameBuffer fb;
    const size_t xStride = 3 * sizeof(float), yStride = xStride * image.width;
    // Imf::Slice wants a mutable pointer for writing too; it only reads through it here.
    char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
    for (int c = 0; c < 3; ++c)
        fb.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride));
    for (const ExrChannel& c : extra)
        fb.insert(c.name, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(c.values.data())),
                                     sizeof(float), sizeof(float) * image.width));

    MemoryOStream stream(path.c_str());
    {
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(fb);
        file.writePixels(static_cast<int>(image.height));
    }  // the destructor writes the line offset table
    return stream.take();
}

}  // namespace

void writeExr(const std::filesystem::path& path, const ImageRgb& image, const ExrAttributes& attributes) {
    writeBytesAtomically(path, exrBytes(path, image, attributes));
}

std::string exrBytes(const std::filesystem::path& path, const ImageRgb& image, const ExrAttributes& attributes,
                     const std::vector<ExrChannel>& extra) {
    if (!isWellFormed(image))
        throw RuntimeError(fmt::format("cannot write {}: the image is empty or has {} values for {}x{} pixels",
                                       path.string(), image.pixels.size(), image.width, image.height));
    if (image.width > uint32_t(INT_MAX) || image.height > uint32_t(INT_MAX))
        throw RuntimeError(fmt::format("cannot write {}: {}x{} is too large for OpenEXR", path.string(),
                                       image.width, image.height));
    std::string bytes;
    try {
        bytes = encodeExr(path, image, attributes, extra);
    } catch (const std::exception& e) {
        throw RuntimeError(fmt::format("cannot write {}: {}", path.string(), e.what()));
    }
    return bytes;
}

ImageRgb readExr(const std::filesystem::path& path, ExrAttributes* attributes) {
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        for (const char* c : kChannels)
            if (!header.channels().findChannel(c))
                throw InputError(fmt::format("{}: not an RGB image (no channel {})", path.string(), c));
        const Imath::Box2i dw = header.dataWindow();
        const int64_t width = int64_t(dw.max.x) - dw.min.x + 1, height = int64_t(dw.max.y) - dw.min.y + 1;
        if (width <= 0 || height <= 0 || uint64_t(width) * uint64_t(height) > kMaxReadPixels)
            throw InputError(fmt::format("{}: unsupported image size {}x{}", path.string(), width, height));

        ImageRgb image = makeImage(uint32_t(width), uint32_t(height));
        Imf::FrameBuffer fb;
        const size_t xStride = 3 * sizeof(float), yStride = xStride * image.width;
        char* base = reinterpret_cast<char*>(image.pixels.data());
        // Slice::Make offsets the base pointer by the data window origin without overflowing.
        for (int c = 0; c < 3; ++c)
            fb.insert(kChannels[c], Imf::Slice::Make(Imf::FLOAT, base + c * sizeof(float), dw, xStride, yStride));
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);

        if (attributes) {
            attributes->clear();
            for (auto it = header.begin(); it != header.end(); ++it)
                if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
                    attributes->emplace_back(it.name(), s->value());
        }
        return image;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(fmt::format("{}: cannot read EXR: {}", path.string(), e.what()));
    }
}

std::vector<std::string> exrChannelNames(const std::filesystem::path& path) {
    try {
        Imf::InputFile file(path.c_str());
        std::vector<std::string> names;
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
            names.push_back(it.name());
        return names;
    } catch (const std::exception& e) {
        throw InputError(fmt::format("{}: cannot read EXR: {}", path.string(), e.what()));
    }
}

std::vector<float> readExrChannel(const std::filesystem::path& path, const std::string& name) {
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        if (!header.channels().findChannel(name))
            throw InputError(fmt::format("{}: no channel {}", path.string(), name));
        const Imath::Box2i dw = header.dataWindow();
        const int64_t width = int64_t(dw.max.x) - dw.min.x + 1, height = int64_t(dw.max.y) - dw.min.y + 1;
        if (width <= 0 || height <= 0 || uint64_t(width) * uint64_t(height) > kMaxReadPixels)
            throw InputError(fmt::format("{}: unsupported image size {}x{}", path.string(), width, height));
        std::vector<float> values(size_t(width) * size_t(height));
        Imf::FrameBuffer fb;
        fb.insert(name, Imf::Slice::Make(Imf::FLOAT, values.data(), dw, sizeof(float), sizeof(float) * size_t(width)));
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        return values;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(fmt::format("{}: cannot read EXR: {}", path.string(), e.what()));
    }
}

}  // namespace vkp
