// How the glTF loader touches the file system and decodes images: only regular files inside the
// scene's folder, never more bytes than the limits allow, no path expansion.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <tiny_gltf.h>

#include "scene/gltf_loader.h"

namespace vkp {

// The canonical path of `relative` (already percent-decoded) when it names a regular file inside
// `folder` (symbolic links resolved, so a link pointing out of the folder does not count).
std::optional<std::filesystem::path> resolveInFolder(const std::filesystem::path& folder,
                                                      const std::filesystem::path& relative);

// tinygltf's file-system and image-decoding callbacks, confined to one folder. Keep it alive
// (and at a fixed address) while tinygltf loads.
class GltfFileAccess {
public:
    GltfFileAccess(std::filesystem::path folder, const GltfLimits& limits);

    // A buffer file may be longer than its buffer's byteLength (the spec allows trailing bytes);
    // tinygltf insists on equality, so reads of this file stop at `byteLength`.
    void expectBufferLength(const std::filesystem::path& canonical, uint64_t byteLength);

    // tinygltf decodes '+' in a URI as a space (form encoding); RFC 3986 makes it a literal. Each
    // external URI is registered here, so the path tinygltf asks for is mapped back to the file the
    // URI names.
    void registerUri(const std::string& uri);

    tinygltf::FsCallbacks callbacks();
    static tinygltf::LoadImageDataFunction imageLoader();  // user data: this object

    // The first image problem, already formatted "images[i]: ..."; tinygltf's own message for it
    // is less precise.
    const std::string& imageError() const { return m_imageError; }

private:
    static bool fileExists(const std::string& path, void* self);
    static std::string expandFilePath(const std::string& path, void* self);
    static bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* self);
    static bool writeWholeFile(std::string* err, const std::string& path, const std::vector<unsigned char>& contents,
                               void* self);
    static bool loadImage(tinygltf::Image* image, int index, std::string* err, std::string* warn, int reqWidth,
                          int reqHeight, const unsigned char* bytes, int size, void* self);
    std::string decodeImage(tinygltf::Image& image, const unsigned char* bytes, int size);
    std::string decodeWebp(tinygltf::Image& image, const unsigned char* bytes, int size);

    std::filesystem::path m_folder;
    GltfLimits m_limits;
    std::map<std::filesystem::path, uint64_t> m_bufferLengths;
    std::map<std::string, std::string> m_plusAsSpace;  // tinygltf's path -> the URI's file
    std::string m_imageError;
    uint64_t m_decodedPixels = 0;  // against maxTotalImagePixels
};

}  // namespace vkp
