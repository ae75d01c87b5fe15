// HAL conformance: fragment-stage storage writes and atomics (what the A-buffer fill needs): a
// depth-only render pass whose fragments append to per-pixel linked lists (atomicAdd on a
// counter, imageAtomicExchange on an R32UI head image), early depth tests rejecting hidden
// fragments before they store anything, a later pass reading the lists, and the counter counting
// past a full pool without a write out of bounds. Refused under the GL ES 3.0 ceiling.
// Runs on whatever backend and tier the run opened (tests/support/hal_fixture.hpp).
#include "hal_fixture.hpp"

using namespace sfx;
using namespace sfx::test;

namespace {

constexpr uint32_t kNull = 0xFFFFFFFFu;

// Two triangles covering the viewport at clip depth z, red channel = value / 255.
void addQuad(std::vector<MeshVertex>& v, float z, float value) {
    const float r = value / 255.0f;
    const float corners[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    for (const auto& p : corners) v.push_back({p[0], p[1], z, r, 0, 0, 1});
}

struct ListRun {
    std::vector<uint32_t> header;  // count, capacity
    std::vector<uint32_t> nodes;   // next, value per node
    std::vector<uint32_t> heads;
    std::vector<uint32_t> walked;  // the read pass's length * 65536 + sum
};

// Three full-viewport quads at clip z 0.1, 0.3 (values 10, 20) in front of the cleared depth
// and 0.9 (value 40) behind it: on both clip conventions ([0, 1] and [-1, 1]) the first two
// pass a depth cleared to 0.7 and the third fails.
ListRun runLists(uint32_t capacity) {
    Cleanup c;
    TextureHandle heads = makeTexture(c, kW, kH, Format::R32UI, kTextureSampled | kTextureStorage);
    std::vector<uint32_t> nullHeads(kW * kH, kNull);
    SFX_REQUIRE_OK(dev().writeTexture(heads, 0, nullHeads.data(), nullHeads.size() * 4));
    TextureHandle depth = makeTexture(c, kW, kH, Format::D32F, kTextureRenderTarget);
    std::vector<uint32_t> pool(2 + 2 * capacity, 0xABABABABu);
    pool[0] = 0;
    pool[1] = capacity;
    // One guard word past the pool: it must survive.
    pool.push_back(0xC0FFEEu);
    BufferHandle lists = makeBuffer(c, pool.size() * 4, kBufferStorage, pool.data());
    std::vector<MeshVertex> mesh;
    addQuad(mesh, 0.1f, 10);
    addQuad(mesh, 0.3f, 20);
    addQuad(mesh, 0.9f, 40);
    BufferHandle vertices = makeBuffer(c, mesh.size() * sizeof(MeshVertex), kBufferVertex, mesh.data());

    GraphicsPipelineDesc fillDesc = meshPipelineDesc(Format::R8, Format::D32F);
    fillDesc.colorFormats.clear();  // no colour attachment: storage side effects only
    fillDesc.depth = {true, false, CompareOp::Less};
    PipelineHandle fill = makePipeline(c, fillDesc, "hal_test_fragment_list");
    RenderPassDesc pass;
    pass.depth = {depth, LoadOp::Clear, 0.7f};
    DrawDesc draw;
    draw.pipeline = fill;
    draw.vertexBuffer = vertices;
    draw.count = uint32_t(mesh.size());
    draw.bindings.storageBuffers = {{gen::hal_test_fragment_list::ListNodes, lists}};
    draw.bindings.storageImages = {{gen::hal_test_fragment_list::uHeads, heads}};
    SFX_REQUIRE_OK(dev().renderPass(pass, {&draw, 1}));

    TextureHandle walked = makeTexture(c, kW, kH, Format::R32UI, kTextureSampled | kTextureRenderTarget);
    PipelineHandle read = fullscreenPipeline(c, "hal_test_fragment_list_read", Format::R32UI);
    fullscreenPass(walked, read,
                   {.storageBuffers = {{gen::hal_test_fragment_list_read::ListNodes, lists}},
                    .storageImages = {{gen::hal_test_fragment_list_read::uHeads, heads}}});

    ListRun run;
    std::vector<uint32_t> all(pool.size());
    SFX_REQUIRE_OK(dev().readBuffer(lists, 0, all.data(), all.size() * 4));
    REQUIRE(all.back() == 0xC0FFEEu);  // nothing written past the pool
    run.header = {all[0], all[1]};
    run.nodes.assign(all.begin() + 2, all.end() - 1);
    run.heads = readLevel<uint32_t>(heads);
    run.walked = readLevel<uint32_t>(walked);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
    return run;
}

}  // namespace

TEST_CASE("hal: fragment stores and atomics are refused under the ceiling", "[hal]") {
    if (test::tier() == Tier::High) {
        CHECK(dev().caps().fragmentStoresAndAtomics);
        return;
    }
    CHECK_FALSE(dev().caps().fragmentStoresAndAtomics);
    Result<ProgramHandle> p = dev().createProgram(program("hal_test_fragment_list", Tier::High));
    CHECK(p.status().code() == StatusCode::UnsupportedFeature);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: a depth-only pass builds per-pixel lists with fragment atomics; a later pass reads them", "[hal]") {
    if (test::tier() == Tier::Current) return;  // the case above covers the ceiling
    REQUIRE(dev().caps().fragmentStoresAndAtomics);
    const uint32_t pixels = kW * kH;
    ListRun run = runLists(4 * pixels);
    // The hidden quad's fragments fail the early depth test and never reach the atomics.
    CHECK(run.header[0] == 2 * pixels);
    CHECK(run.header[1] == 4 * pixels);
    for (uint32_t i = 0; i < pixels; ++i) {
        INFO("pixel " << i);
        uint32_t node = run.heads[i], length = 0, sum = 0;
        while (node != kNull && length < 8) {
            REQUIRE(node < 2 * pixels);
            sum += run.nodes[2 * node + 1];
            node = run.nodes[2 * node];
            ++length;
        }
        REQUIRE(length == 2);
        REQUIRE(sum == 30);
        REQUIRE(run.walked[i] == 2 * 65536 + 30);
    }
}

TEST_CASE("hal: a full pool counts every fragment and stores none past its end", "[hal]") {
    if (test::tier() == Tier::Current) return;
    const uint32_t pixels = kW * kH;
    const uint32_t capacity = pixels / 2 + 3;
    ListRun run = runLists(capacity);
    CHECK(run.header[0] == 2 * pixels);  // counted, stored or not
    uint32_t stored = 0;
    for (uint32_t i = 0; i < pixels; ++i) {
        uint32_t node = run.heads[i], length = 0;
        while (node != kNull && length < 8) {
            REQUIRE(node < capacity);
            node = run.nodes[2 * node];
            ++length;
        }
        REQUIRE(length <= 2);
        REQUIRE(run.walked[i] / 65536 == length);
        stored += length;
    }
    CHECK(stored == capacity);
}
