#include "scene/gltf_files.h"

#include "scene/gltf_uri_policy.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>

#include <fmt/format.h>
#include <stb/stb_image.h>
#include <webp/decode.h>

namespace vkp {

namespace fs = std::filesystem;

std::optional<fs::path> resolveInFolder(const fs::path& folder, const fs::path& candidate) {
    std::error_code ec;
    const fs::path root = fs::canonical(folder, ec);
    if (ec) return std::nullopt;
    const fs::path file = fs::canonical(candidate, ec);  // resolves links; fails when missing
    if (ec || !fs::is_regular_file(file, ec)) return std::nullopt;
    // Inside means: the folder's components are a prefix of the file's.
    const auto [rootEnd, fileAt] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
    if (rootEnd != root.end() || fileAt == file.end()) return std::nullopt;
    return file;
}

GltfFileAccess::GltfFileAccess(fs::path folder, const GltfLimits& limits)
    : m_folder(std::move(folder)), m_limits(limits) {}

void GltfFileAccess::expectBufferLength(const fs::path& canonical, uint64_t byteLength) {
    m_bufferLengths[canonical] = byteLength;
}

void GltfFileAccess::registerUri(const std::string& uri) {
    const std::string decoded = uriToRelativePath(uri);
    std::string raw = uri;  // tinygltf's decoding: '+' becomes ' ', then the %-escapes
    std::replace(raw.begin(), raw.end(), '+', ' ');
    const std::string asTinygltf = uriToRelativePath(raw);
    if (asTinygltf == decoded) return;
    // tinygltf joins its base folder (the scene's folder) and the decoded URI with one '/'.
    const std::string base = m_folder.string();
    const auto join = [&](const std::string& name) {
        return base.empty() ? name : base.back() == '/' ? base + name : base + "/" + name;
    };
    m_plusAsSpace.emplace(join(asTinygltf), join(decoded));
}

tinygltf::FsCallbacks GltfFileAccess::callbacks() {
    return {&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, this};
}

tinygltf::LoadImageDataFunction GltfFileAccess::imageLoader() { return &loadImage; }

bool GltfFileAccess::fileExists(const std::string& path, void* self) {
    return resolveInFolder(static_cast<GltfFileAccess*>(self)->m_folder, path).has_value();
}

// tinygltf's default expands "~" and environment variables: a scene must not reach those.
// '+' read back as a literal (registerUri).
std::string GltfFileAccess::expandFilePath(const std::string& path, void* self) {
    const auto& map = static_cast<GltfFileAccess*>(self)->m_plusAsSpace;
    const auto it = map.find(path);
    return it == map.end() ? path : it->second;
}

bool GltfFileAccess::readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                                   void* self) {
    auto* access = static_cast<GltfFileAccess*>(self);
    const auto fail = [&](const std::string& why) {
        if (err) *err += why + "\n";
        return false;
    };
    const auto file = resolveInFolder(access->m_folder, path);
    if (!file) return fail(fmt::format("'{}' is missing or outside the scene's folder", path));
    std::error_code ec;
    uint64_t size = fs::file_size(*file, ec);
    if (ec) return fail(fmt::format("cannot stat '{}': {}", path, ec.message()));
    if (size > access->m_limits.maxFileBytes)
        return fail(fmt::format("'{}' is larger than the {}-byte limit", path, access->m_limits.maxFileBytes));
    if (const auto it = access->m_bufferLengths.find(*file); it != access->m_bufferLengths.end())
        size = std::min(size, it->second);
    std::ifstream in(*file, std::ios::binary);
    out->resize(size);
    if (!in || (size && !in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))))
        return fail(fmt::format("cannot read '{}'", path));
    return true;
}

bool GltfFileAccess::writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "the glTF loader never writes files\n";
    return false;
}

bool GltfFileAccess::loadImage(tinygltf::Image* image, int index, std::string* err, std::string*, int, int,
                               const unsigned char* bytes, int size, void* self) {
    auto* access = static_cast<GltfFileAccess*>(self);
    const std::string problem = access->decodeImage(*image, bytes, size);
    if (problem.empty()) return true;
    const std::string message = fmt::format("images[{}]: {}", index, problem);
    if (access->m_imageError.empty()) access->m_imageError = message;
    if (err) *err += message + "\n";
    return false;
}

namespace {

uint32_t bigEndian32(const unsigned char* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

uint32_t crc32(const unsigned char* data, size_t size) {
    static const auto table = [] {
        std::array<uint32_t, 256> t{};
        for (uint32_t n = 0; n < 256; ++n) {
            uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xff] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

// stb decodes damaged files without a word (a truncated PNG or JPEG comes out partly grey, a
// JPEG without scan data as a flat image), so the structure is checked first: every PNG chunk
// inside the data with its CRC, IHDR first, IDAT, IEND; JPEG segments inside the data, a frame
// header (SOFn) before the first scan (SOS), scan data, and the end-of-image marker.
std::string pngProblem(const unsigned char* bytes, size_t size) {
    size_t at = 8;
    bool header = false, data = false;
    while (true) {
        if (at + 12 > size) return "the PNG is truncated (no IEND chunk)";
        const uint32_t length = bigEndian32(bytes + at);
        const std::string type(reinterpret_cast<const char*>(bytes + at + 4), 4);
        for (const char c : type)
            if (!std::isalpha(static_cast<unsigned char>(c))) return fmt::format("the PNG has a malformed chunk at byte {}", at);
        if (length > size - at - 12) return fmt::format("the PNG is truncated in its {} chunk", type);
        if (crc32(bytes + at + 4, length + 4) != bigEndian32(bytes + at + 8 + length))
            return fmt::format("the PNG's {} chunk at byte {} fails its CRC check (damaged file)", type, at);
        if (!header && type != "IHDR") return "the PNG does not start with an IHDR chunk";
        header = true;
        data = data || type == "IDAT";
        at += 12 + size_t(length);
        if (type == "IEND") return data ? "" : "the PNG has no image data (no IDAT chunk)";
    }
}

std::string jpegProblem(const unsigned char* bytes, size_t size) {
    size_t at = 2;  // after SOI
    bool frame = false, scan = false;
    while (true) {
        if (at + 2 > size) return scan ? "the JPEG is truncated (no end-of-image marker)" : "the JPEG is truncated";
        if (bytes[at] != 0xff) return fmt::format("the JPEG has a malformed segment at byte {}", at);
        const unsigned char marker = bytes[at + 1];
        if (marker == 0xff) { ++at; continue; }  // fill byte
        if (marker == 0xd9) {
            if (!scan) return "the JPEG has no image data (no start-of-scan segment)";
            return "";
        }
        if ((marker >= 0xd0 && marker <= 0xd7) || marker == 0x01 || marker == 0xd8) { at += 2; continue; }
        if (at + 4 > size) return "the JPEG is truncated";
        const size_t length = size_t(bytes[at + 2]) << 8 | bytes[at + 3];
        if (length < 2 || at + 2 + length > size) return fmt::format("the JPEG is truncated in a segment at byte {}", at);
        if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc) frame = true;
        at += 2 + length;
        if (marker != 0xda) continue;
        if (!frame) return "the JPEG has a scan before its frame header (SOF)";
        // Entropy-coded data runs to the next marker that is neither a stuffed 0xff00 nor a restart.
        const size_t start = at;
        while (at + 1 < size && !(bytes[at] == 0xff && bytes[at + 1] != 0 && !(bytes[at + 1] >= 0xd0 && bytes[at + 1] <= 0xd7)))
            ++at;
        if (at == start) return "the JPEG's scan holds no data";
        scan = true;
    }
}

}  // namespace

// Decodes a PNG or JPEG into tinygltf::Image with its own channel count (1-4) and bit depth
// (8 or 16), a WebP (EXT_texture_webp) as 8-bit RGBA; the texture code converts to RGBA8. The
// header is checked against the limits before anything is allocated. Returns what is wrong, or "".
std::string GltfFileAccess::decodeImage(tinygltf::Image& image, const unsigned char* bytes, int size) {
    static constexpr unsigned char kPngMagic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static constexpr unsigned char kJpegMagic[3] = {0xff, 0xd8, 0xff};
    if (bytes == nullptr || size <= 0) return "no image data";
    const bool png = size >= 8 && std::memcmp(bytes, kPngMagic, 8) == 0;
    const bool jpeg = size >= 3 && std::memcmp(bytes, kJpegMagic, 3) == 0;
    const bool webp = size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0;
    if (webp) return decodeWebp(image, bytes, size);
    if (!png && !jpeg) return "not a PNG or JPEG image (nor a WebP, which EXT_texture_webp allows)";
    const char* format = png ? "PNG" : "JPEG";
    // A JPEG's size comes from stb, which needs the structure; a PNG's from its IHDR, so that
    // an oversized PNG is refused for its size even when only its header is there.
    if (const std::string problem = jpeg ? jpegProblem(bytes, size_t(size)) : ""; !problem.empty()) return problem;
    int width = 0, height = 0, components = 0;
    // stb refuses PNGs over 1 GiB with a vague reason, so a PNG's size is read from its IHDR
    // chunk (signature, length, "IHDR", big-endian width and height) to name the real problem.
    if (png && size >= 24 && std::memcmp(bytes + 12, "IHDR", 4) == 0) {
        const auto bigEndian = [&](int at) {
            return uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 | uint32_t(bytes[at + 2]) << 8 | bytes[at + 3];
        };
        width = static_cast<int>(std::min<uint32_t>(bigEndian(16), INT32_MAX));
        height = static_cast<int>(std::min<uint32_t>(bigEndian(20), INT32_MAX));
    } else if (!stbi_info_from_memory(bytes, size, &width, &height, &components)) {
        return fmt::format("unreadable {} header", format);  // stb's reason names the last format it tried
    }
    if (width <= 0 || height <= 0 || static_cast<uint32_t>(width) > m_limits.maxImageDimension ||
        static_cast<uint32_t>(height) > m_limits.maxImageDimension ||
        uint64_t(width) * uint64_t(height) > m_limits.maxImagePixels)
        return fmt::format("{}x{} pixels exceeds the image size limit ({} per side, {} pixels in all)", width, height,
                           m_limits.maxImageDimension, m_limits.maxImagePixels);
    if (const std::string problem = png ? pngProblem(bytes, size_t(size)) : ""; !problem.empty()) return problem;
    // tinygltf decodes every image, used or not: many small files of huge images must not add up.
    m_decodedPixels += uint64_t(width) * uint64_t(height);
    if (m_decodedPixels > m_limits.maxTotalImagePixels)
        return fmt::format("the file's images add up to more than the limit of {} pixels", m_limits.maxTotalImagePixels);
    const bool sixteenBit = stbi_is_16_bit_from_memory(bytes, size);
    void* pixels = sixteenBit ? static_cast<void*>(stbi_load_16_from_memory(bytes, size, &width, &height, &components, 0))
                              : static_cast<void*>(stbi_load_from_memory(bytes, size, &width, &height, &components, 0));
    if (pixels == nullptr) return fmt::format("cannot decode the {} ({})", format, stbi_failure_reason());
    const size_t byteCount = size_t(width) * size_t(height) * size_t(components) * (sixteenBit ? 2 : 1);
    image.width = width;
    image.height = height;
    image.component = components;
    image.bits = sixteenBit ? 16 : 8;
    image.pixel_type = sixteenBit ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.image.assign(static_cast<const unsigned char*>(pixels), static_cast<const unsigned char*>(pixels) + byteCount);
    stbi_image_free(pixels);
    return {};
}

// EXT_texture_webp: libwebp reads the size from the header (checked against the limits first)
// and decodes lossy and lossless WebP, with or without alpha, to RGBA8.
std::string GltfFileAccess::decodeWebp(tinygltf::Image& image, const unsigned char* bytes, int size) {
    int width = 0, height = 0;
    if (!WebPGetInfo(bytes, size_t(size), &width, &height)) return "unreadable WebP header";
    if (width <= 0 || height <= 0 || static_cast<uint32_t>(width) > m_limits.maxImageDimension ||
        static_cast<uint32_t>(height) > m_limits.maxImageDimension ||
        uint64_t(width) * uint64_t(height) > m_limits.maxImagePixels)
        return fmt::format("{}x{} pixels exceeds the image size limit ({} per side, {} pixels in all)", width, height,
                           m_limits.maxImageDimension, m_limits.maxImagePixels);
    m_decodedPixels += uint64_t(width) * uint64_t(height);
    if (m_decodedPixels > m_limits.maxTotalImagePixels)
        return fmt::format("the file's images add up to more than the limit of {} pixels", m_limits.maxTotalImagePixels);
    uint8_t* pixels = WebPDecodeRGBA(bytes, size_t(size), &width, &height);
    if (pixels == nullptr) return "cannot decode the WebP";
    image.width = width;
    image.height = height;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.image.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
    WebPFree(pixels);
    return {};
}

}  // namespace vkp
