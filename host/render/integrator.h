// The seam every integrator implements (docs/architecture.md, "Adding an integrator"). The
// driver (render/renderer.h) owns the frame, the film, the sample loop, progress, the time limit
// and Ctrl-C; an integrator builds what its samples need and records them.
//
//   prepare(frame, film)          once per frame: photon maps, guides; binds the film
//   beginSamples(first, count)    host work before a batch (SPPM: the pass's photon map)
//   recordSamples(cmd, first, n)  records samples [first, first + n) into the film: no submit
//   recordSamplePart(cmd, s, px)  (optional) sample s of some of the pixels only, so a consumer
//                                 that must bound each submission (the viewer) can split one
//   finish(image, samples)        adds what the film's sums do not hold (SPPM's photon estimate;
//                                 progressiveEstimates() is its buffer for device-side resolves)
//   report(stats)                 named statistics, its resolved settings, warnings
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <vulkan/vulkan.h>

#include "image/image.h"
#include "vk/compute_kernel.h"
#include "render/film.h"
#include "render/frame.h"
#include "render/stats.h"

namespace vkp {
namespace vk { class Buffer; }

// Parts of a sample (Integrator::recordSamplePart) start at multiples of this many pixels from the
// window's first, so that every part's invocations fall into the same workgroups and SIMD batches
// as in a whole-frame dispatch (lavapipe runs a batch's lanes together, and its loop budget counts
// a batch's iterations: with parts cut elsewhere, pixels near a cut came out differently).
constexpr uint64_t kSamplePartGranule = 256;

class Integrator {
public:
    virtual ~Integrator() = default;

    // The name the statistics and the EXR header give ("photon (progressive)").
    virtual std::string name() const = 0;
    // Builds what this frame's samples need; may submit work and wait for it.
    virtual void prepare(const Frame& frame, const Film& film) = 0;
    // Most samples per pixel one submission may hold (the driver grows batches up to it).
    virtual uint32_t maxSamplesPerBatch() const = 0;
    // Host work before the batch [first, first + count) is recorded; may submit and wait.
    virtual void beginSamples(uint32_t first, uint32_t count) {
        (void)first;
        (void)count;
    }
    // Records samples [first, first + count) of every pixel into the film. Record only.
    virtual void recordSamples(VkCommandBuffer cmd, uint32_t first, uint32_t count) = 0;
    // Whether recordSamplePart() works (every built-in integrator's does).
    virtual bool recordsSampleParts() const { return false; }
    // Whether beginSamples() does work worth running beside the window's loop (SPPM's photon
    // pass); the viewer then runs it on a thread of its own.
    virtual bool beginsWithHostWork() const { return false; }
    // Records sample `sample` of the pixels in `part` (a range of the frame's pixelRange()) into
    // the film: the same values recordSamples gives those pixels. The parts of one sample, each
    // recorded once after one beginSamples(sample, 1), may go in separate submissions. Record only.
    virtual void recordSamplePart(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange part) {
        (void)cmd;
        (void)sample;
        (void)part;
    }
    // After the last batch: adds to the film's resolved means what they do not hold.
    virtual void finish(ImageRgb& image, uint32_t samplesDone) {
        (void)image;
        (void)samplesDone;
    }
    // The device buffer finish() reads what it adds from, for consumers that resolve the image
    // on the device (the viewer's display pass): one gpu::SppmPixel per pixel, added as
    // gpu::sppmRadiance(pixel, samplesDone); null when finish() adds nothing.
    virtual const vk::Buffer* progressiveEstimates() const { return nullptr; }
    // Why prepare() (or a later photon pass) stopped before finishing ("interrupted", "time
    // limit"), when it did: the frame's control was set and the phase kept what it had.
    virtual std::optional<std::string> stoppedEarly() const { return std::nullopt; }
    // Statistics under the keys of docs/usage (e.g. "photons.globalStored", "settings.photon.radius").
    virtual void report(Stats& stats) const = 0;
};

}  // namespace vkp
