// The OIT CPU references: sorted compositing against the analytic over operator, independence of
// fragment order, transparent and opaque limits, the K-layer limit with its tail, the list
// compression's criterion, weighted blended OIT's exact and approximate cases, the node layout,
// and sfx_shared_oit.h compiling as GLSL for every target.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "sfx/reference/oit_reference.hpp"
#include "sfx/shader_compiler.hpp"
#include "sfx_shared_oit.h"

using namespace sfx;
using namespace sfx::reference;
using glm::dvec3;

namespace {

OitFragment layer(dvec3 color, double alpha, double depth, uint32_t drawIndex = 0, uint32_t primitiveId = 0) {
    OitFragment f;
    f.color = color;
    f.alpha = alpha;
    f.depth = depth;
    f.drawIndex = drawIndex;
    f.primitiveId = primitiveId;
    return f;
}

OpaqueSurface opaqueAt(dvec3 color, double depth) {
    OpaqueSurface o;
    o.color = color;
    o.depth = depth;
    return o;
}

// The over operator written out: layer i (sorted near to far) contributes
// alpha_i * c_i * prod_{j < i} (1 - alpha_j); the opaque colour gets the product of all.
dvec3 analyticOver(const std::vector<OitFragment>& nearToFar, dvec3 opaque) {
    dvec3 sum(0.0);
    for (size_t i = 0; i < nearToFar.size(); ++i) {
        double front = 1.0;
        for (size_t j = 0; j < i; ++j) front *= 1.0 - nearToFar[j].alpha;
        sum += nearToFar[i].alpha * nearToFar[i].color * front;
    }
    double all = 1.0;
    for (const OitFragment& f : nearToFar) all *= 1.0 - f.alpha;
    return sum + all * opaque;
}

void requireNear(dvec3 a, dvec3 b, double tolerance) {
    for (int c = 0; c < 3; ++c) REQUIRE(std::abs(a[c] - b[c]) <= tolerance);
}

std::vector<OitFragment> randomStack(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<OitFragment> out;
    for (int i = 0; i < n; ++i)
        out.push_back(layer(dvec3(u(rng), u(rng), u(rng)), 0.05 + 0.9 * u(rng), 1.0 + 10.0 * u(rng), uint32_t(i), uint32_t(i * 7)));
    return out;
}

}  // namespace

TEST_CASE("oit: N layers at known depths composite to the analytic over operator", "[oit]") {
    const dvec3 background(0.2, 0.4, 0.9);
    std::vector<OitFragment> stack;
    const dvec3 colors[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    for (int i = 0; i < 6; ++i) stack.push_back(layer(colors[i], 0.1 + 0.15 * i, 1.0 + i, uint32_t(i)));
    for (size_t n = 0; n <= stack.size(); ++n) {
        std::vector<OitFragment> first(stack.begin(), stack.begin() + long(n));
        requireNear(compositeExact(first, opaqueAt(background, 50.0)), analyticOver(first, background), 1e-14);
    }
    // Two layers by hand: 0.5 red over 0.5 green over blue.
    const dvec3 two = compositeExact({layer({0, 1, 0}, 0.5, 3.0), layer({1, 0, 0}, 0.5, 2.0)}, opaqueAt({0, 0, 1}, 10.0));
    requireNear(two, dvec3(0.5, 0.25, 0.25), 1e-15);
    // Fragments behind the opaque surface fail the depth test.
    requireNear(compositeExact({layer({1, 0, 0}, 0.5, 12.0)}, opaqueAt({0, 0, 1}, 10.0)), dvec3(0, 0, 1), 0.0);
}

TEST_CASE("oit: any fragment order gives bit-identical results, ties ordered by id", "[oit]") {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<OitFragment> frags = randomStack(rng, 12);
        // Equal depths: the draw index, then the primitive id, decide.
        frags.push_back(layer({1, 0, 0}, 0.6, 2.5, 40, 1));
        frags.push_back(layer({0, 1, 0}, 0.6, 2.5, 40, 0));
        frags.push_back(layer({0, 0, 1}, 0.6, 2.5, 39, 9));
        const OpaqueSurface o = opaqueAt({0.3, 0.3, 0.3}, 8.0);
        const dvec3 exact = compositeExact(frags, o), kept = compositeKept(frags, o, 5), wb = compositeWeightedBlended(frags, o);
        for (int s = 0; s < 5; ++s) {
            std::shuffle(frags.begin(), frags.end(), rng);
            CHECK(compositeExact(frags, o) == exact);
            CHECK(compositeKept(frags, o, 5) == kept);
            CHECK(compositeWeightedBlended(frags, o) == wb);
        }
        const std::vector<OitFragment> sorted = sortedFragments(frags, o.depth);
        for (size_t i = 1; i < sorted.size(); ++i)
            CHECK(shared::oitBefore(sorted[i - 1].depth, sorted[i - 1].drawIndex, sorted[i - 1].primitiveId, sorted[i].depth, sorted[i].drawIndex,
                                    sorted[i].primitiveId));
    }
    const std::vector<OitFragment> tie = sortedFragments(
        {layer({1, 0, 0}, 0.5, 2, 3, 1), layer({0, 1, 0}, 0.5, 2, 3, 0), layer({0, 0, 1}, 0.5, 2, 2, 5)}, 10.0);
    CHECK(tie[0].drawIndex == 2);
    CHECK(tie[1].primitiveId == 0);
    CHECK(tie[2].primitiveId == 1);
}

TEST_CASE("oit: opacity 0 changes nothing, opacity 1 is the opaque path", "[oit]") {
    std::mt19937 rng(11);
    const OpaqueSurface o = opaqueAt({0.5, 0.1, 0.2}, 20.0);
    for (int trial = 0; trial < 10; ++trial) {
        std::vector<OitFragment> frags = randomStack(rng, 8);
        const dvec3 before = compositeExact(frags, o), beforeWb = compositeWeightedBlended(frags, o);
        std::vector<OitFragment> more = frags;
        for (int i = 0; i < 5; ++i) more.push_back(layer({1, 1, 1}, 0.0, 0.5 + 3.0 * i, uint32_t(100 + i)));
        CHECK(compositeExact(more, o) == before);
        CHECK(compositeWeightedBlended(more, o) == beforeWb);
        // An opaque layer: the same as an opaque surface at its depth with the layers in front.
        const double d = 5.0;
        std::vector<OitFragment> withWall = frags;
        withWall.push_back(layer({0.9, 0.8, 0.7}, 1.0, d, 99));
        std::vector<OitFragment> inFront;
        for (const OitFragment& f : frags)
            if (f.depth < d) inFront.push_back(f);
        CHECK(compositeExact(withWall, o) == compositeExact(inFront, opaqueAt({0.9, 0.8, 0.7}, d)));
    }
    requireNear(compositeExact({layer({0.25, 0.5, 0.75}, 1.0, 1.0)}, o), dvec3(0.25, 0.5, 0.75), 0.0);
}

TEST_CASE("oit: the K-layer limit keeps the nearest K exact and blends the tail", "[oit]") {
    std::mt19937 rng(3);
    const OpaqueSurface o = opaqueAt({0.1, 0.2, 0.3}, 30.0);
    for (int trial = 0; trial < 20; ++trial) {
        const std::vector<OitFragment> frags = randomStack(rng, 20);
        const std::vector<OitFragment> sorted = sortedFragments(frags, o.depth);
        for (uint32_t k : {1u, 4u, 16u}) {
            // Independent expectation: the front K by the over operator, then the tail as one layer
            // of coverage 1 - prod(1 - alpha) and alpha-weighted mean colour, then the opaque colour.
            std::vector<OitFragment> front(sorted.begin(), sorted.begin() + k);
            double frontT = 1.0, tailT = 1.0, alphaSum = 0.0;
            dvec3 tailSum(0.0);
            for (const OitFragment& f : front) frontT *= 1.0 - f.alpha;
            for (size_t i = k; i < sorted.size(); ++i) {
                tailT *= 1.0 - sorted[i].alpha;
                alphaSum += sorted[i].alpha;
                tailSum += sorted[i].alpha * sorted[i].color;
            }
            const dvec3 tail = tailSum / alphaSum * (1.0 - tailT) + tailT * o.color;
            const dvec3 expected = analyticOver(front, dvec3(0.0)) + frontT * tail;
            const dvec3 kept = compositeKept(frags, o, k);
            requireNear(kept, expected, 1e-12);
            // The error against the exact result is bounded by what the front K let through.
            const dvec3 exact = compositeExact(frags, o);
            for (int c = 0; c < 3; ++c) CHECK(std::abs(kept[c] - exact[c]) <= frontT + 1e-12);
        }
        CHECK(compositeKept(frags, o, 20) == compositeExact(frags, o));
        CHECK(compositeKept(frags, o, 64) == compositeExact(frags, o));
    }
    // A tail of one colour is exact: only the order of equal colours was lost.
    std::vector<OitFragment> grey;
    for (int i = 0; i < 10; ++i) grey.push_back(layer(i < 3 ? dvec3(1, 0, 0) : dvec3(0.5), 0.3, 1.0 + i, uint32_t(i)));
    requireNear(compositeKept(grey, o, 3), compositeExact(grey, o), 1e-14);
}

TEST_CASE("oit compression: front nodes stay and the drop criterion is alpha * (1 - z)", "[oit][compression]") {
    CompressionConfig cc;
    cc.nodes = 4;
    cc.zNear = 0.0;
    cc.zFar = 10.0;
    const OpaqueSurface sky;  // nothing opaque
    const double maxDepth = 100.0;
    // Up to M fragments: all kept, sorted, the rest empty.
    std::vector<CompressedNode> n = compressList({layer({1, 1, 1}, 0.5, 6.0), layer({1, 1, 1}, 0.2, 2.0)}, sky, maxDepth, cc);
    REQUIRE(n.size() == 4);
    CHECK(n[0].depth == Approx(0.2));
    CHECK(n[1].depth == Approx(0.6));
    CHECK(n[2].opacity == 0.0);
    CHECK(n[2].depth == 1.0);
    // Five fragments (z' = 0.1 .. 0.5). Keep values alpha (1 - z'): 0.09, 0.72, 0.56, 0.06, 0.25.
    const std::vector<OitFragment> five = {layer({1, 1, 1}, 0.1, 1.0), layer({1, 1, 1}, 0.9, 2.0), layer({1, 1, 1}, 0.8, 3.0),
                                           layer({1, 1, 1}, 0.1, 4.0), layer({1, 1, 1}, 0.5, 5.0)};
    cc.backHalfOnly = false;
    n = compressList(five, sky, maxDepth, cc);  // drops the faint node at z' = 0.4 (0.06)
    CHECK(n[0].depth == Approx(0.1));
    CHECK(n[1].depth == Approx(0.2));
    CHECK(n[2].depth == Approx(0.3));
    CHECK(n[3].depth == Approx(0.5));
    std::vector<OitFragment> frontFaint = five;
    frontFaint[0].alpha = 0.01;  // now the front node is the least important: dropped
    n = compressList(frontFaint, sky, maxDepth, cc);
    CHECK(n[0].depth == Approx(0.2));
    cc.backHalfOnly = true;  // ... unless only the back half may go
    n = compressList(frontFaint, sky, maxDepth, cc);
    CHECK(n[0].depth == Approx(0.1));
    CHECK(n[1].depth == Approx(0.2));
    // Opaque geometry enters at opacity 1 and, near, outranks faint layers.
    std::vector<OitFragment> many;
    for (int i = 0; i < 8; ++i) many.push_back(layer({1, 1, 1}, 0.05, 1.0 + 0.5 * i, uint32_t(i)));
    n = compressList(many, opaqueAt({1, 1, 1}, 6.0), maxDepth, cc);
    CHECK(n[3].depth == Approx(0.6));
    CHECK(n[3].opacity == 1.0);
    CHECK(n[0].depth == Approx(0.1));  // the front half kept
    CHECK(n[1].depth == Approx(0.15));
    // The 24-byte texel: 16-bit depth, 8-bit opacity.
    const std::vector<CompressedNode> q = quantizeCompressed(n);
    for (size_t i = 0; i < 4; ++i) {
        CHECK(std::abs(q[i].depth - n[i].depth) <= 0.5 / 65535.0 + 1e-12);
        CHECK(std::abs(q[i].opacity - n[i].opacity) <= 0.5 / 255.0 + 1e-12);
    }
}

TEST_CASE("oit wboit: exact for one layer, the documented error for two", "[oit][wboit]") {
    const OpaqueSurface o = opaqueAt({0.2, 0.6, 0.1}, 40.0);
    for (double a : {0.1, 0.5, 0.9, 1.0})
        for (double z : {0.2, 3.0, 70.0}) {
            const std::vector<OitFragment> one = {layer({0.8, 0.3, 0.5}, a, z)};
            requireNear(compositeWeightedBlended(one, o), compositeExact(one, o), 1e-12);
        }
    const dvec3 s1(1, 0, 0), s2(0, 0, 1);
    for (double a : {0.1, 0.5, 0.9}) {
        const std::vector<OitFragment> two = {layer(s1, a, 2.0, 0), layer(s2, a, 2.0, 1)};  // s1 in front (draw 0)
        const OpaqueSurface black = opaqueAt(dvec3(0.0), 40.0);
        const dvec3 wb = compositeWeightedBlended(two, black), exact = compositeExact(two, black);
        requireNear(wb, (s1 + s2) * 0.5 * a * (2.0 - a), 1e-12);
        requireNear(wb - exact, a * a * 0.5 * (s2 - s1), 1e-12);
    }
    // The weight's documented range: saturated in front of it, floored behind it.
    CHECK(shared::oitWeightedBlendedWeight(0.001, 1.0) == Approx(shared::SFX_OIT_WBOIT_MAX_WEIGHT));
    CHECK(shared::oitWeightedBlendedWeight(2.0 * shared::SFX_OIT_WBOIT_DEPTH_MAX, 1.0) == Approx(shared::SFX_OIT_WBOIT_MIN_WEIGHT));
    CHECK(shared::oitWeightedBlendedWeight(1.0, 1.0) > shared::oitWeightedBlendedWeight(10.0, 1.0));
}

TEST_CASE("oit node layout round-trips", "[oit]") {
    glm::uvec4 lo, hi;
    const glm::dvec4 c(0.25, 0.5, 0.125, 0.75);
    const dvec3 n = glm::normalize(dvec3(0.3, -0.5, -0.8));
    shared::oitPackNode(c, 3.75, n, false, 12345, 678, 42, lo, hi);
    CHECK(shared::oitNodeColor(lo) == c);  // exact in fp16
    CHECK(shared::oitNodeDepth(lo) == 3.75);
    CHECK(glm::length(shared::oitNodeNormal(lo) - n) < 1e-3);
    CHECK(shared::oitDrawIndex(hi.x) == 12345u);
    CHECK_FALSE(shared::oitFrontFacing(hi.x));
    CHECK(shared::oitFrontFacing(shared::oitPackIdWord(7, true)));
    CHECK(hi.y == 678u);
    CHECK(hi.z == 42u);
    for (const dvec3& d : {dvec3(0, 0, 1), dvec3(0, 0, -1), dvec3(1, 0, 0), dvec3(-0.6, 0.0, -0.8), dvec3(0.48, 0.6, 0.64)}) {
        CHECK(glm::length(shared::oitOctDecode(shared::oitOctEncode(d)) - d) < 1e-12);
        CHECK(glm::length(shared::oitCompressedNormal(glm::uvec2(shared::oitPackCompressedNormal(d), 0u), 0) - d) < 0.02);
    }
}

TEST_CASE("sfx_shared_oit.h compiles as GLSL for every target", "[oit][shaders]") {
    // Every function of the header used, so none is stripped before the GLSL back ends see it.
    const char* body = R"(#version 450
#include "sfx_shared_oit.h"
layout(location = 0) out vec4 o0;
layout(location = 1) out vec4 o1;
void main() {
    uvec4 lo, hi;
    vec4 c = vec4(gl_FragCoord.xyxy * 0.01);
    oitPackNode(c, gl_FragCoord.z, vec3(0.0, 0.0, 1.0), gl_FrontFacing, 3u, uint(gl_FragCoord.x), SFX_OIT_NULL_INDEX, lo, hi);
    vec4 acc = vec4(0.0, 0.0, 0.0, 1.0);
    if (oitBefore(oitNodeDepth(lo), oitDrawIndex(hi.x), hi.y, 1.0, 0u, 0u) && oitFrontFacing(hi.x)) oitCompositeFront(acc, oitNodeColor(lo));
    vec4 tail = vec4(0.0);
    float tailT = 1.0;
    oitTailAccumulate(tail, tailT, c);
    oitCompositeFront(acc, oitTailLayer(tail, tailT));
    float d[SFX_OIT_MAX_COMPRESSED_NODES + 1], a[SFX_OIT_MAX_COMPRESSED_NODES + 1];
    int count = 0;
    oitCompressInsert(d, a, count, SFX_OIT_COMPRESSED_NODES, true, oitNormalizedDepth(c.x, 0.1, 100.0), c.w);
    uvec4 nodes = uvec4(oitPackCompressedDepths(d[0], d[1]), oitPackCompressedDepths(d[2], d[3]),
                        oitPackCompressedOpacities(a[0], a[1], a[2], a[3]), uint(count));
    uvec2 normals = uvec2(oitPackCompressedNormal(oitNodeNormal(lo)), 0u);
    float occ = oitAlchemyOcclusion(c.x, c.y, c.z, 0.5, 0.01, 1e-4, oitExteriorWeight(c.w, oitCompressedFrontFacing(nodes, 1)),
                                    oitCompressedOpacity(nodes, 0)) +
                oitScalableOcclusion(c.x, c.y, 0.5, 0.01, 1e-4, 0.5, oitCompressedDepth(nodes, 1)) +
                float(oitCompressedCount(nodes)) + oitCompressedNormal(normals, 0).x;
    vec4 t0, t1;
    oitWeightedBlendedOutputs(c, occ, t0, t1);
    o0 = vec4(oitCompositeFinish(acc, oitWeightedBlendedResolve(t0, t1, vec3(0.5))), 1.0);
    o1 = t1;
}
)";
    for (Tier tier : {Tier::Current, Tier::High}) {
        shaderc::StageSource src{ShaderStage::Fragment, "oit_header_check.frag", body};
        shaderc::CompileOptions opts;
        opts.tier = tier;
        opts.includeDirs = {std::string(SFX_SOURCE_DIR) + "/shader_src/include"};
        Result<CompiledProgram> p = shaderc::compileProgram("oit_header_check", {src}, opts);
        INFO(p.status().message());
        REQUIRE(p.isOk());
    }
}
