// A project that uses an installed ScalableFX (find_package(ScalableFX CONFIG)) or the source
// tree (add_subdirectory), as an engine would. The region between the sfx-readme markers is
// README.md's "Using it from an engine" code character for character
// (tests/check_readme_snippet.sh compares them; laid out by hand for the page, so clang-format
// leaves it alone); main() below runs it on a GL ES device and
// checks the AO it computes, so the README's code cannot rot.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string_view>
#include <vector>

#include "sfx/backends.hpp"
#include "sfx/budget.hpp"

// clang-format off
// sfx-readme-begin
#include "sfx/ao.hpp"
#include "sfx/tiers.hpp"
#include "sfx/vulkan_device.hpp"   // or sfx/gl_device.hpp: sfx::gl::wrapCurrentContext(...)

namespace engine {

struct HostVulkan {  // what your renderer already has
    VkInstance instance;
    VkPhysicalDevice physicalDevice;
    VkDevice device;
    VkQueue queue;
    uint32_t queueFamily;
    PFN_vkGetInstanceProcAddr getInstanceProcAddr;
};
struct FrameTextures {           // SDK textures: Device::createTexture
    sfx::TextureHandle depth;    // hardware depth, or linear depth (R32F)
    sfx::TextureHandle normals;  // view-space normals, when settings.normals == FromTexture
    sfx::TextureHandle ao;       // where visibility goes
    sfx::DepthKind depthKind;
};

// Once: hand the SDK your own Vulkan objects; it never destroys them, and they (and the
// returned device) must outlive every effect created on it.
sfx::Result<std::unique_ptr<sfx::Device>> wrapHostDevice(const HostVulkan& host) {
    sfx::DeviceOptions options;
    options.validation = false;  // true while developing: Khronos layer / GL error checks
    options.log = [](sfx::LogSeverity, std::string_view message) { std::cerr << message << "\n"; };
    return sfx::vulkan::wrapDevice({host.instance, host.physicalDevice, host.device, host.queue,
                                    host.queueFamily, host.getInstanceProcAddr}, options);
}

// Once per size and settings: the effect allocates what it needs here, not per frame.
sfx::Result<std::unique_ptr<sfx::AmbientObscurance>> createAo(sfx::Device& device, uint32_t width, uint32_t height,
                                                              sfx::DepthKind depthKind) {
    auto tier = sfx::tiers::choose(device.caps());                // or force sfx::Tier::Current
    if (!tier) return tier.status();                              // names the unmet requirement
    std::cout << tier->reason << "\n";                            // why this tier

    sfx::AoSettings settings;                                     // ranges: docs/settings.md; bad
    settings.radius = 0.5f;                                       // values are named errors, not clamps
    settings.metresPerUnit = 1.0f;                                // your world's scale (0.01: centimetres)
    settings.intensity = std::nullopt;                            // unset: the tier's calibrated value
    auto ao = sfx::AmbientObscurance::create(device, {width, height, tier->profile, settings, depthKind});
    if (ao) std::cout << ao.value()->plan().describe();           // passes and bytes it holds
    return ao;
}

// Every frame: record into your frame's command buffer (Vulkan), or the current context (GL).
sfx::Status renderAo(sfx::Device& device, sfx::AmbientObscurance& ao, VkCommandBuffer frameCommandBuffer,
                     const FrameTextures& frame, const glm::dmat4& projection) {
    if (device.caps().backend == sfx::BackendKind::Vulkan)
        SFX_TRY(sfx::vulkan::setCommandBuffer(device, frameCommandBuffer));
    sfx::CameraProjection camera{projection, sfx::ClipDepthRange::ZeroToOne};
    return ao.dispatch({{frame.depth, frame.depthKind, camera}, frame.normals, frame.ao});
}

}  // namespace engine
// sfx-readme-end
// clang-format on

// ---- The consumer test: the code above on a GL ES device, on a tiny synthetic G-buffer ----

namespace {

constexpr uint32_t kWidth = 64, kHeight = 48;
constexpr float kFar = 2.0f, kNear = 1.75f;  // a step 0.25 units towards the camera, inside the 0.5 AO radius

int fail(const std::string& what) {
    std::cerr << "consumer: FAILED: " << what << "\n";
    return 1;
}

// The budget library links from the package: candidates from each tier's presets, and a choice
// on a hand-made cost table (no device timing, so it runs without a GPU).
int checkBudget() {
    for (const sfx::tiers::TierRow& row : sfx::tiers::table()) {
        std::vector<sfx::budget::Candidate> candidates = sfx::budget::candidates(sfx::budget::Effect::AmbientObscurance,
                                                                                 sfx::tiers::row(row.tier).presets);
        if (candidates.empty()) return fail(std::string("no AO budget candidates for tier ") + sfx::toString(row.tier));
        sfx::budget::CostTable table;
        table.device = "consumer";
        table.tier = row.tier;
        table.width = kWidth;
        table.height = kHeight;
        for (size_t i = 0; i < candidates.size(); ++i)  // dearer the later, so the budget decides
            table.entries.push_back({candidates[i], 1.0 + double(i)});
        sfx::Result<sfx::budget::Choice> cheapest = sfx::budget::choose(table, 1.0);
        if (!cheapest) return fail("budget::choose: " + cheapest.status().toString());
        if (cheapest->chosen.candidate.name() != candidates.front().name()) return fail("a 1 ms budget chose " + cheapest->chosen.candidate.name());
        double bestPsnr = 0;
        for (const sfx::budget::Candidate& c : candidates) bestPsnr = std::max(bestPsnr, c.psnrDb);
        sfx::Result<sfx::budget::Choice> any = sfx::budget::choose(table, 1000.0);
        if (!any || any->chosen.candidate.psnrDb != bestPsnr) return fail("a budget every entry fits did not choose the most accurate");
        sfx::Result<sfx::budget::Choice> none = sfx::budget::choose(table, 0.5);
        if (none || none.status().code() != sfx::StatusCode::OverBudget)
            return fail("a budget under every cost is not OverBudget: " + none.status().toString());
    }
    return 0;
}

}  // namespace

int main() {
    if (int failed = checkBudget()) return failed;

    // wrapHostDevice links and runs: without host objects it is a named error, not a crash.
    sfx::Result<std::unique_ptr<sfx::Device>> none = engine::wrapHostDevice({});
    if (none || none.status().code() != sfx::StatusCode::InvalidArgument) return fail("wrapDevice on no Vulkan objects: " + none.status().toString());
    if (none.value() != nullptr) return fail("an error Result's value is not a null device");

    sfx::BackendConfig config;
    if (!sfx::parseBackendConfig("gles", &config)) return fail("gles is not a backend name");
    sfx::DeviceOptions options;
    options.validation = true;  // tests ask for API validation
    std::vector<std::string> logged;
    options.log = [&](sfx::LogSeverity, std::string_view message) { logged.emplace_back(message); };
    sfx::Result<std::unique_ptr<sfx::Device>> opened = sfx::openDevice(config, options);
    if (!opened) {
        std::cout << "consumer: skipped, no GL ES device: " << opened.status().toString() << "\n";
        return 77;
    }
    sfx::Device& device = *opened.value();

    // Linear depth: a wall at kFar whose right half steps forward to kNear.
    std::vector<float> depth(kWidth * kHeight);
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) depth[y * kWidth + x] = x < kWidth / 2 ? kFar : kNear;
    sfx::Result<sfx::TextureHandle> depthTexture = device.createTexture(
        {kWidth, kHeight, 1, sfx::Format::R32F, sfx::kTextureSampled, "consumer depth"});
    sfx::Result<sfx::TextureHandle> aoTexture = device.createTexture(
        {kWidth, kHeight, 1, sfx::Format::R32F, sfx::kTextureSampled | sfx::kTextureRenderTarget, "consumer ao"});
    if (!depthTexture || !aoTexture) return fail("textures: " + depthTexture.status().toString() + aoTexture.status().toString());
    if (sfx::Status st = device.writeTexture(*depthTexture, 0, depth.data(), depth.size() * sizeof(float)); !st) return fail(st.toString());

    sfx::Result<std::unique_ptr<sfx::AmbientObscurance>> ao = engine::createAo(device, kWidth, kHeight, sfx::DepthKind::Linear);
    if (!ao) return fail("createAo: " + ao.status().toString());
    sfx::Result<sfx::CameraProjection> camera = sfx::makePerspective({1.0471975511965976, double(kWidth) / kHeight, 0.1, 100.0});
    if (!camera) return fail(camera.status().toString());
    engine::FrameTextures frame{*depthTexture, {}, *aoTexture, sfx::DepthKind::Linear};
    for (int f = 0; f < 3; ++f)  // a few frames, as a renderer runs them
        if (sfx::Status st = engine::renderAo(device, **ao, VK_NULL_HANDLE, frame, camera->projection); !st)
            return fail("renderAo: " + st.toString());
    if (sfx::Status st = device.flush(); !st) return fail(st.toString());

    std::vector<float> visibility(kWidth * kHeight);
    if (sfx::Status st = device.readTexture(*aoTexture, 0, visibility.data(), visibility.size() * sizeof(float)); !st) return fail(st.toString());
    // Open wall (left quarter, far from the step): nothing occludes it, and nothing is in front
    // of the step's near side either. The far side right at the step has the nearer half inside
    // the radius in front of it, so it is darker, the more so the closer to the step (with
    // Scalable's falloff, by about 1% here: the checks ask for half of that).
    const uint32_t row = kHeight / 2;
    const float open = visibility[row * kWidth + 4];
    const float creased = visibility[row * kWidth + kWidth / 2 - 1];
    const float nearCreased = visibility[row * kWidth + kWidth / 2 - 6];
    const float stepTop = visibility[row * kWidth + kWidth / 2];
    std::printf("consumer: visibility open %.4f, at the step %.4f\n", open, creased);
    for (float v : visibility)
        if (!(v >= 0.0f && v <= 1.0f)) return fail("visibility outside [0, 1]");
    if (!(open > 0.95f)) return fail("the open wall is occluded");
    if (!(creased < open - 0.005f)) return fail("the step does not occlude the wall behind it");
    if (!(creased < nearCreased && nearCreased < open)) return fail("occlusion does not grow towards the step");
    if (!(std::fabs(stepTop - open) < 0.002f)) return fail("the step's near side, open above, is occluded");

    std::vector<std::string> messages = device.takeValidationMessages();
    for (const std::string& m : messages) std::cerr << "validation: " << m << "\n";
    if (!messages.empty() || !logged.empty()) return fail("validation messages");
    ao.value().reset();  // effects go before their device
    std::cout << "consumer: PASS on " << device.caps().summary() << "\n";
    return 0;
}
