// Image output: EXR round trips and attributes, PNG contents, atomic writes that fail without
// leftovers, and the image metrics (the display transform: view_transform_test.cpp).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

// The decoder only checks what the PNG writer produced; static so that it cannot clash with the
// copy libstb.so exports.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include "image/atomic_file.h"
#include "image/exr.h"
#include "image/image.h"
#include "image/metrics.h"
#include "image/png.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;

fs::path tempDir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("vkphoton-image-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Every entry under `dir`, relative, sorted: what a failed write must not change.
std::vector<std::string> listing(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir)) names.push_back(fs::relative(e.path(), dir).string());
    std::sort(names.begin(), names.end());
    return names;
}

bool hasTemporaryFiles(const fs::path& dir) {
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.path().filename().string().find(".tmp-") != std::string::npos) return true;
    return false;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Random radiance with the awkward values a film can hold: zeros, huge and tiny magnitudes.
ImageRgb randomImage(uint32_t w, uint32_t h, uint32_t seed = 9) {
    ImageRgb image = makeImage(w, h);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = i % 7 == 0 ? 0.0f : (i % 11 == 0 ? 1.0e6f * u(rng) : u(rng));
    return image;
}

// --- EXR ----------------------------------------------------------------------------------------

TEST(Exr, RoundTripIsBitExactWithAttributes) {
    const fs::path path = tempDir("exr") / "film.exr";
    ImageRgb image = randomImage(37, 23);
    const float special[] = {0.0f, -0.0f, FLT_MAX, FLT_MIN, std::numeric_limits<float>::denorm_min(), 3.0e38f,
                             -1.5f, 1.0e-30f, INFINITY, std::numeric_limits<float>::quiet_NaN()};
    for (size_t i = 0; i < std::size(special); ++i) image.pixels[5 * i] = special[i];
    const std::string longName = "vkphoton/a-name-longer-than-thirty-one-characters";
    writeExr(path, image,
             {{"vkphoton/spp", "64"}, {"vkphoton/partial", "false"}, {longName, "long"}, {"vkphoton/empty", ""},
              {"vkphoton/scene", "scènes/box 1.gltf\nsecond line"}});
    ExrAttributes attributes;
    const ImageRgb back = readExr(path, &attributes);
    ASSERT_EQ(back.width, image.width);
    ASSERT_EQ(back.height, image.height);
    ASSERT_EQ(back.pixels.size(), image.pixels.size());
    EXPECT_EQ(std::memcmp(back.pixels.data(), image.pixels.data(), image.pixels.size() * sizeof(float)), 0);
    const std::map<std::string, std::string> found(attributes.begin(), attributes.end());
    EXPECT_EQ(found.size(), 5u);  // only the string attributes: none of OpenEXR's own are strings
    EXPECT_EQ(found.at("vkphoton/spp"), "64");
    EXPECT_EQ(found.at("vkphoton/partial"), "false");
    EXPECT_EQ(found.at(longName), "long");
    EXPECT_EQ(found.at("vkphoton/empty"), "");
    EXPECT_EQ(found.at("vkphoton/scene"), "scènes/box 1.gltf\nsecond line");
    EXPECT_FALSE(hasTemporaryFiles(path.parent_path()));
}

TEST(Exr, IsFloatRgbWithZipCompression) {
    const fs::path path = tempDir("exr-format") / "film.exr";
    writeExr(path, randomImage(8, 4));
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    EXPECT_EQ(header.compression(), Imf::ZIP_COMPRESSION);
    int channels = 0;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it, ++channels)
        EXPECT_EQ(it.channel().type, Imf::FLOAT) << it.name();
    EXPECT_EQ(channels, 3);
    for (const char* c : {"R", "G", "B"}) EXPECT_NE(header.channels().findChannel(c), nullptr) << c;
}

TEST(Exr, OverwritesAnExistingFile) {
    const fs::path path = tempDir("exr-overwrite") / "film.exr";
    writeExr(path, randomImage(9, 9, 1), {{"run", "first"}});
    const ImageRgb second = randomImage(5, 3, 2);
    writeExr(path, second, {{"run", "second"}});
    ExrAttributes attributes;
    const ImageRgb back = readExr(path, &attributes);
    EXPECT_EQ(back.pixels, second.pixels);
    ASSERT_EQ(attributes.size(), 1u);
    EXPECT_EQ(attributes[0].second, "second");
    EXPECT_EQ(listing(path.parent_path()), std::vector<std::string>{"film.exr"});
}

TEST(Exr, ReadsHalfRgbaWithAnOffsetDataWindow) {
    const fs::path path = tempDir("exr-half") / "rgba.exr";
    const Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(9, 9));
    const Imath::Box2i data(Imath::V2i(-3, 2), Imath::V2i(1, 4));  // 5 x 3, origin off the corner
    const int w = 5, h = 3;
    std::vector<Imf::Rgba> pixels(w * h);
    for (int i = 0; i < w * h; ++i) pixels[i] = Imf::Rgba(half(0.25f * i), half(1000.0f + i), half(-0.5f), half(0.5f));
    {
        Imf::RgbaOutputFile out(path.c_str(), display, data, Imf::WRITE_RGBA);
        out.setFrameBuffer(pixels.data() - data.min.x - data.min.y * w, 1, w);
        out.writePixels(h);
    }
    const ImageRgb image = readExr(path);
    ASSERT_EQ(image.width, uint32_t(w));
    ASSERT_EQ(image.height, uint32_t(h));
    for (int i = 0; i < w * h; ++i) {
        EXPECT_EQ(image.pixels[3 * i + 0], float(pixels[i].r)) << i;
        EXPECT_EQ(image.pixels[3 * i + 1], float(pixels[i].g)) << i;
        EXPECT_EQ(image.pixels[3 * i + 2], -0.5f) << i;
    }
}

TEST(Exr, ReadingAFileWithoutRgbIsAnInputError) {
    const fs::path path = tempDir("exr-y") / "luma.exr";
    {
        Imf::Header header(4, 4);
        header.channels().insert("Y", Imf::Channel(Imf::HALF));
        std::vector<half> y(16, half(1.0f));
        Imf::FrameBuffer fb;
        fb.insert("Y", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(y.data()), sizeof(half), 4 * sizeof(half)));
        Imf::OutputFile out(path.c_str(), header);
        out.setFrameBuffer(fb);
        out.writePixels(4);
    }
    try {
        readExr(path);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no channel R"), std::string::npos) << e.what();
    }
}

TEST(Exr, ReadingGarbageOrNothingIsAnInputError) {
    const fs::path dir = tempDir("exr-garbage");
    std::ofstream(dir / "bad.exr") << "not an exr";
    EXPECT_THROW(readExr(dir / "bad.exr"), InputError);
    // A real EXR cut short.
    writeExr(dir / "whole.exr", randomImage(64, 64));
    const std::string bytes = readFile(dir / "whole.exr");
    std::ofstream(dir / "cut.exr", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    EXPECT_THROW(readExr(dir / "cut.exr"), InputError);
    EXPECT_THROW(readExr(dir / "missing.exr"), InputError);
}

TEST(Exr, FailureUnderARegularFileThrowsAndLeavesNoFiles) {
    const fs::path dir = tempDir("exr-fail");
    std::ofstream(dir / "file") << "x";
    const fs::path target = dir / "file" / "sub" / "x.exr";
    try {
        writeExr(target, randomImage(4, 4));
        FAIL() << "expected RuntimeError";
    } catch (const RuntimeError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(target.string()), std::string::npos) << message;
        EXPECT_NE(message.find("not a directory"), std::string::npos) << message;
    }
    EXPECT_EQ(listing(dir), std::vector<std::string>{"file"});
}

TEST(Exr, FailureInAReadOnlyDirectoryLeavesNoFiles) {
    if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only directories";
    const fs::path dir = tempDir("exr-readonly");
    fs::create_directory(dir / "ro");
    fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_THROW(writeExr(dir / "ro" / "x.exr", randomImage(4, 4)), RuntimeError);
    fs::permissions(dir / "ro", fs::perms::owner_all);
    EXPECT_EQ(listing(dir), std::vector<std::string>{"ro"});
}

TEST(Exr, FailureOnADirectoryTargetLeavesItAlone) {
    const fs::path dir = tempDir("exr-dir");
    fs::create_directory(dir / "x.exr");
    EXPECT_THROW(writeExr(dir / "x.exr", randomImage(4, 4)), RuntimeError);
    EXPECT_TRUE(fs::is_directory(dir / "x.exr"));
    EXPECT_EQ(listing(dir), std::vector<std::string>{"x.exr"});
}

TEST(Exr, RejectsBadImagesAndAttributesWithoutWriting) {
    const fs::path dir = tempDir("exr-bad");
    ImageRgb short3 = makeImage(4, 4);
    short3.pixels.pop_back();
    EXPECT_THROW(writeExr(dir / "a.exr", short3), RuntimeError);
    EXPECT_THROW(writeExr(dir / "b.exr", ImageRgb{}), RuntimeError);
    EXPECT_THROW(writeExr(dir / "c.exr", randomImage(2, 2), {{"", "empty name"}}), RuntimeError);
    // A standard attribute that is not a string cannot be replaced by one.
    EXPECT_THROW(writeExr(dir / "d.exr", randomImage(2, 2), {{"compression", "zip"}}), RuntimeError);
    EXPECT_TRUE(listing(dir).empty());
}

// --- atomic writes ------------------------------------------------------------------------------

TEST(AtomicFile, CreatesParentsAndReplacesContent) {
    const fs::path dir = tempDir("atomic");
    const fs::path path = dir / "a" / "b" / "stats.json";
    writeTextAtomically(path, "first");
    writeTextAtomically(path, "second, longer");
    EXPECT_EQ(readFile(path), "second, longer");
    writeBytesAtomically(path, std::string_view("\0\1\2", 3));
    EXPECT_EQ(readFile(path), std::string("\0\1\2", 3));
    EXPECT_FALSE(hasTemporaryFiles(dir));
}

TEST(AtomicFile, AFailingWriterKeepsTheOldFileAndLeavesNoTemporary) {
    const fs::path dir = tempDir("atomic-fail");
    const fs::path path = dir / "out.txt";
    writeTextAtomically(path, "old");
    try {
        writeAtomically(path, [](const fs::path& temp) {
            std::ofstream(temp) << "half";
            throw std::runtime_error("encoder exploded");
        });
        FAIL() << "expected RuntimeError";
    } catch (const RuntimeError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
        EXPECT_NE(message.find("encoder exploded"), std::string::npos) << message;
    }
    EXPECT_EQ(readFile(path), "old");
    EXPECT_EQ(listing(dir), std::vector<std::string>{"out.txt"});
}

// An EXR and its PNG are replaced together or not at all.
TEST(AtomicFile, FilesWrittenTogetherAreReplacedTogetherOrNotAtAll) {
    const fs::path dir = tempDir("atomic-together");
    writeFilesTogether({{dir / "a.exr", "exr 1"}, {dir / "a.png", "png 1"}});
    writeFilesTogether({{dir / "a.exr", "exr 2"}, {dir / "a.png", "png 2"}});
    EXPECT_EQ(readFile(dir / "a.exr"), "exr 2");
    EXPECT_EQ(readFile(dir / "a.png"), "png 2");
    fs::create_directories(dir / "b.png");  // the second target cannot be written
    writeTextAtomically(dir / "b.exr", "old");
    EXPECT_THROW(writeFilesTogether({{dir / "b.exr", "new"}, {dir / "b.png", "new"}}), RuntimeError);
    EXPECT_EQ(readFile(dir / "b.exr"), "old");
    EXPECT_FALSE(hasTemporaryFiles(dir));
}

// Outputs are checked before the work; the check leaves nothing behind.
TEST(AtomicFile, CheckWritableRefusesWhatCannotBeWritten) {
    const fs::path dir = tempDir("atomic-check");
    EXPECT_NO_THROW(checkWritable(dir / "new" / "x.exr"));
    EXPECT_TRUE(fs::is_directory(dir / "new"));
    EXPECT_THROW(checkWritable(dir), RuntimeError);                          // a directory
    EXPECT_THROW(checkWritable(dir / (std::string(300, 'a') + ".exr")), RuntimeError);  // name too long
    EXPECT_THROW(checkWritable("/proc/vkphoton-test.exr"), RuntimeError);    // cannot create files there
    std::ofstream(dir / "file") << "x";
    EXPECT_THROW(checkWritable(dir / "file" / "x.exr"), RuntimeError);      // under a regular file
    EXPECT_FALSE(hasTemporaryFiles(dir));
}

TEST(AtomicFile, RefusesToReplaceSpecialFiles) {
    const fs::path dir = tempDir("atomic-fifo");
    ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
    EXPECT_THROW(writeTextAtomically(dir / "pipe", "x"), RuntimeError);
    EXPECT_TRUE(fs::is_fifo(dir / "pipe"));
    EXPECT_THROW(writeTextAtomically("", "x"), RuntimeError);
    EXPECT_EQ(listing(dir), std::vector<std::string>{"pipe"});
}

TEST(AtomicFile, ConcurrentWritersOfOneTargetDoNotCollide) {
    const fs::path dir = tempDir("atomic-threads");
    const fs::path path = dir / "same.txt";
    const std::string a(100000, 'a'), b(100000, 'b');
    std::thread t1([&] { for (int i = 0; i < 20; ++i) writeTextAtomically(path, a); });
    std::thread t2([&] { for (int i = 0; i < 20; ++i) writeTextAtomically(path, b); });
    t1.join();
    t2.join();
    const std::string content = readFile(path);
    EXPECT_TRUE(content == a || content == b);
    EXPECT_EQ(listing(dir), std::vector<std::string>{"same.txt"});
}

// --- PNG ----------------------------------------------------------------------------------------

TEST(Png, HoldsTheTonemappedSrgbBytes) {
    const fs::path dir = tempDir("png");
    const fs::path path = dir / "a" / "b.png";
    ImageRgb image = randomImage(16, 8);
    image.pixels[1] = std::numeric_limits<float>::quiet_NaN();
    image.pixels[2] = INFINITY;
    image.pixels[4] = -3.0f;
    for (const DisplaySettings display : {DisplaySettings{}, DisplaySettings{ViewTransform::AcesFit, -2.0f},
                                          DisplaySettings{ViewTransform::Clamp, 1.5f}}) {
        writePng(path, image, display);
        const std::string bytes = readFile(path);
        ASSERT_GE(bytes.size(), 8u);
        EXPECT_EQ(std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8), 0);
        int w = 0, h = 0, channels = 0;
        stbi_uc* decoded = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()),
                                                 &w, &h, &channels, 0);
        ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
        EXPECT_EQ(w, 16);
        EXPECT_EQ(h, 8);
        EXPECT_EQ(channels, 3);
        size_t mismatches = 0;
        for (size_t i = 0; i < image.pixels.size(); i += 3) {
            const auto expected = toDisplayBytes(glm::make_vec3(&image.pixels[i]), display);
            for (int c = 0; c < 3; ++c) mismatches += decoded[i + c] != expected[c];
        }
        stbi_image_free(decoded);
        EXPECT_EQ(mismatches, 0u) << viewTransformName(display.view) << " EV " << display.exposureEv;
    }
    EXPECT_FALSE(hasTemporaryFiles(dir));
}

TEST(Png, RejectsBadInputsWithoutWriting) {
    const fs::path dir = tempDir("png-bad");
    EXPECT_THROW(writePng(dir / "a.png", randomImage(2, 2), {ViewTransform::AgX, NAN}), InputError);
    EXPECT_THROW(writePng(dir / "a.png", randomImage(2, 2), {ViewTransform::AgX, 100.0f}), InputError);
    EXPECT_THROW(writePng(dir / "a.png", ImageRgb{3, 3, {}}), RuntimeError);
    std::ofstream(dir / "file") << "x";
    EXPECT_THROW(writePng(dir / "file" / "b.png", randomImage(2, 2)), RuntimeError);
    EXPECT_EQ(listing(dir), std::vector<std::string>{"file"});
}

// --- metrics ------------------------------------------------------------------------------------

TEST(Metrics, RelativeMse) {
    const ImageRgb a = randomImage(8, 8);
    EXPECT_EQ(relativeMse(a, a), 0.0);
    ImageRgb b = a;
    for (float& v : b.pixels) v += 0.1f;
    EXPECT_GT(relativeMse(b, a), 0.0);
    const ImageRgb ones{1, 1, {1, 1, 1}}, zeros{1, 1, {0, 0, 0}}, twos{1, 1, {2, 2, 2}};
    EXPECT_DOUBLE_EQ(relativeMse(ones, zeros), 100.0);  // 1 / (0 + 1e-2)
    EXPECT_DOUBLE_EQ(relativeMse(twos, ones), 1.0 / 1.01);
    const ImageRgb mixed{2, 1, {1, 1, 1, 2, 2, 2}}, reference{2, 1, {1, 1, 1, 1, 1, 1}};
    EXPECT_DOUBLE_EQ(relativeMse(mixed, reference), 0.5 / 1.01);
    EXPECT_THROW(relativeMse(randomImage(2, 3), randomImage(3, 2)), InputError);
}

TEST(Metrics, MeansAndLuminance) {
    ImageRgb flat{2, 1, {1, 2, 3, 3, 4, 5}};
    EXPECT_DOUBLE_EQ(meanValue(flat), 3.0);
    const auto mean = meanRadiance(flat);
    EXPECT_DOUBLE_EQ(mean[0], 2.0);
    EXPECT_DOUBLE_EQ(mean[1], 3.0);
    EXPECT_DOUBLE_EQ(mean[2], 4.0);
    EXPECT_NEAR(luminance(1, 1, 1), 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(luminance(0, 1, 0), 0.7152);
    EXPECT_NEAR(meanLuminance(flat), 0.2126 * 2 + 0.7152 * 3 + 0.0722 * 4, 1e-12);
    EXPECT_EQ(meanRadiance(ImageRgb{})[0], 0.0);
    EXPECT_TRUE(allFinite(flat));
    flat.pixels[4] = INFINITY;
    EXPECT_FALSE(allFinite(flat));
    flat.pixels[4] = NAN;
    EXPECT_FALSE(allFinite(flat));
}

TEST(Image, Shape) {
    const ImageRgb image = makeImage(3, 2);
    EXPECT_EQ(image.pixels.size(), 18u);
    EXPECT_TRUE(isWellFormed(image));
    EXPECT_FALSE(isWellFormed(ImageRgb{}));
    EXPECT_FALSE(isWellFormed(ImageRgb{3, 2, std::vector<float>(17)}));
    EXPECT_EQ(image.at(2, 1), image.pixels.data() + 15);
}

}  // namespace
}  // namespace vkp
