#include "image/exr.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fmt/format.h>

#include "image/atomic_file.h"
#include "util/errors.h"

namespace vkp {

void writeExr(const std::filesystem::path& path, const ImageRgb& image, const ExrAttributes& attributes) {
    if (image.width == 0 || image.height == 0 || image.pixels.size() != size_t(image.width) * image.height * 3)
        throw RuntimeError(fmt::format("cannot write {}: empty or inconsistent image", path.string()));
    writeAtomically(path, [&](const std::filesystem::path& temp) {
        Imf::Header header(static_cast<int>(image.width), static_cast<int>(image.height));
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
        for (const auto& [key, value] : attributes) header.insert(key, Imf::StringAttribute(value));
        Imf::FrameBuffer fb;
        const size_t xStride = 3 * sizeof(float), yStride = xStride * image.width;
        char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
        fb.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
        fb.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
        fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
        Imf::OutputFile file(temp.c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(static_cast<int>(image.height));
    });
}

ImageRgb readExr(const std::filesystem::path& path, ExrAttributes* attributes) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i dw = file.header().dataWindow();
        ImageRgb image;
        image.width = static_cast<uint32_t>(dw.max.x - dw.min.x + 1);
        image.height = static_cast<uint32_t>(dw.max.y - dw.min.y + 1);
        image.pixels.assign(size_t(image.width) * image.height * 3, 0.0f);
        Imf::FrameBuffer fb;
        const size_t xStride = 3 * sizeof(float), yStride = xStride * image.width;
        char* base = reinterpret_cast<char*>(image.pixels.data()) -
                     (size_t(dw.min.x) * xStride + size_t(dw.min.y) * yStride);
        fb.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
        fb.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
        fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        if (attributes) {
            attributes->clear();
            for (auto it = file.header().begin(); it != file.header().end(); ++it)
                if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
                    attributes->emplace_back(it.name(), s->value());
        }
        return image;
    } catch (const std::exception& e) {
        throw InputError(fmt::format("{}: cannot read EXR: {}", path.string(), e.what()));
    }
}

}  // namespace vkp
