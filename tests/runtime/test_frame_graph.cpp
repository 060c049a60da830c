// The frame graph on the cases of Guy's Filament mobile talk (its slides on tilers):
// colour + post merges and discards HDR and depth; a shadow map and a bloom chain, which sample
// whole textures, do not merge and keep what later passes sample.
#include <gtest/gtest.h>

#include "facet/runtime/frame_graph.h"
#include "facet/runtime/render_path.h"

namespace {

using namespace facet::runtime;
using namespace facet::runtime::fg;

constexpr uint32_t kW = 1920, kH = 1080;
constexpr uint64_t kPixels = uint64_t{kW} * kH;

CompiledGraph compileOrFail(const FrameGraph& graph) {
  CompiledGraph compiled;
  std::string error;
  EXPECT_TRUE(graph.compile(&compiled, &error)) << error;
  return compiled;
}

TEST(FrameGraph, ColourAndPostMergeIntoOneRenderPassAndDiscardHdrAndDepth) {
  ForwardPostGraph g = buildForwardPostGraph(kW, kH, PostPath::Merged, false);
  const CompiledGraph c = compileOrFail(g.graph);
  ASSERT_EQ(c.renderPasses.size(), 1u) << describe(g.graph, c);
  EXPECT_EQ(c.renderPasses[0].subpasses, (std::vector<uint32_t>{g.forwardPass, g.postPass}));
  const Attachment* hdr = c.attachment(0, g.hdr);
  const Attachment* depth = c.attachment(0, g.depth);
  const Attachment* ldr = c.attachment(0, g.ldr);
  ASSERT_TRUE(hdr && depth && ldr);
  EXPECT_EQ(hdr->load, LoadOp::Clear);
  EXPECT_EQ(hdr->store, StoreOp::DontCare);
  EXPECT_TRUE(hdr->inputAttachment);
  EXPECT_EQ(depth->load, LoadOp::Clear);
  EXPECT_EQ(depth->store, StoreOp::DontCare);
  EXPECT_FALSE(depth->inputAttachment);
  EXPECT_EQ(ldr->load, LoadOp::DontCare);  // never written before: nothing to load
  EXPECT_EQ(ldr->store, StoreOp::Store);
  EXPECT_TRUE(c.traffic[g.hdr].transient);
  EXPECT_TRUE(c.traffic[g.depth].transient);
  EXPECT_FALSE(c.traffic[g.ldr].transient);
  EXPECT_EQ(c.loadedBytes(), 0u);
  EXPECT_EQ(c.storedBytes(), kPixels * 4);
  EXPECT_EQ(c.sampledBytes(), 0u);
}

TEST(FrameGraph, SeparatePostStoresHdrAndSamplesItBack) {
  ForwardPostGraph g = buildForwardPostGraph(kW, kH, PostPath::Separate, false);
  const CompiledGraph c = compileOrFail(g.graph);
  ASSERT_EQ(c.renderPasses.size(), 2u) << describe(g.graph, c);
  EXPECT_EQ(c.attachment(0, g.hdr)->store, StoreOp::Store);
  EXPECT_EQ(c.attachment(0, g.depth)->store, StoreOp::DontCare);
  EXPECT_FALSE(c.attachment(0, g.hdr)->inputAttachment);
  EXPECT_EQ(c.attachment(1, g.ldr)->store, StoreOp::Store);
  EXPECT_EQ(c.attachment(1, g.hdr), nullptr);
  EXPECT_FALSE(c.traffic[g.hdr].transient);
  EXPECT_TRUE(c.traffic[g.depth].transient);
  EXPECT_EQ(c.storedBytes(), kPixels * (8 + 4));
  EXPECT_EQ(c.sampledBytes(), kPixels * 8);
}

TEST(FrameGraph, MergedPathStoresAtMostHalfOfTheSeparatePath) {
  const ForwardPostGraph merged = buildForwardPostGraph(kW, kH, PostPath::Merged, false);
  const ForwardPostGraph separate = buildForwardPostGraph(kW, kH, PostPath::Separate, false);
  EXPECT_LE(2 * compileOrFail(merged.graph).storedBytes(), compileOrFail(separate.graph).storedBytes());
}

TEST(FrameGraph, ReadingHdrBackAfterTheFrameStoresItEvenWhenMerged) {
  ForwardPostGraph g = buildForwardPostGraph(64, 32, PostPath::Merged, true);
  const CompiledGraph c = compileOrFail(g.graph);
  ASSERT_EQ(c.renderPasses.size(), 1u);
  EXPECT_EQ(c.attachment(0, g.hdr)->store, StoreOp::Store);
  EXPECT_FALSE(c.traffic[g.hdr].transient);
  EXPECT_EQ(c.storedBytes(), 64u * 32 * (8 + 4));
}

// MSAA (Filament's mobile recipe): the samples of colour and depth stay in tile memory and only
// the resolved colour can reach DRAM, so 4x stores and samples exactly the bytes of 1x on both paths.
TEST(FrameGraph, MsaaSamplesAreTransientAndAddNoStoredBytes) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(toString(path));
    const ForwardPostGraph one = buildForwardPostGraph(kW, kH, path, false);
    const ForwardPostGraph four = buildForwardPostGraph(kW, kH, path, false, HdrFormat::Rgba16Float, 4);
    const CompiledGraph c1 = compileOrFail(one.graph);
    const CompiledGraph c4 = compileOrFail(four.graph);
    ASSERT_EQ(c4.renderPasses.size(), c1.renderPasses.size()) << describe(four.graph, c4);
    EXPECT_NE(four.hdrSamples, four.hdr);
    EXPECT_EQ(four.graph.resource(four.hdrSamples).samples, 4u);
    EXPECT_EQ(four.graph.resource(four.depth).samples, 4u);
    EXPECT_TRUE(c4.traffic[four.hdrSamples].transient) << describe(four.graph, c4);
    EXPECT_TRUE(c4.traffic[four.depth].transient);
    const Attachment* samples = c4.attachment(0, four.hdrSamples);
    const Attachment* resolved = c4.attachment(0, four.hdr);
    ASSERT_TRUE(samples && resolved);
    EXPECT_EQ(samples->load, LoadOp::Clear);
    EXPECT_EQ(samples->store, StoreOp::DontCare);
    EXPECT_EQ(resolved->load, LoadOp::DontCare);  // the resolve overwrites every pixel
    EXPECT_EQ(resolved->inputAttachment, path == PostPath::Merged);
    EXPECT_EQ(c4.traffic[four.hdr].transient, c1.traffic[one.hdr].transient);
    EXPECT_EQ(c4.loadedBytes(), c1.loadedBytes());
    EXPECT_EQ(c4.storedBytes(), c1.storedBytes());
    EXPECT_EQ(c4.sampledBytes(), c1.sampledBytes());
    EXPECT_NE(describe(four.graph, c4).find("hdr_ms 4x"), std::string::npos);
  }
  // Stored, the samples would be four times the image: what keeping them in the tile saves.
  FrameGraph graph;
  const ResourceId ms = graph.addResource({"ms", kW, kH, 8, false, true, 4});
  graph.addPass({"draw", {}, {ms}, {ms}});
  EXPECT_EQ(compileOrFail(graph).storedBytes(), kPixels * 8 * 4);
}

// Per-sample tone mapping (Vulkan's portable merged path): the post subpass reads the
// multisampled HDR, its own pixel's samples, as an input attachment of the same render pass, so it
// stays transient and 4x still stores and samples exactly the bytes of 1x. With HDR read back the
// resolve is stored, as without per-sample reads; the separate path never reads the samples.
TEST(FrameGraph, ToneMappingEachSampleKeepsTheSamplesTransient) {
  const ForwardPostGraph one = buildForwardPostGraph(kW, kH, PostPath::Merged, false);
  const CompiledGraph c1 = compileOrFail(one.graph);
  const ForwardPostGraph four =
      buildForwardPostGraph(kW, kH, PostPath::Merged, false, HdrFormat::Rgba16Float, 4, false, 1.0, 0, 0, true);
  const CompiledGraph c4 = compileOrFail(four.graph);
  ASSERT_EQ(c4.renderPasses.size(), 1u) << describe(four.graph, c4);
  const Attachment* samples = c4.attachment(0, four.hdrSamples);
  ASSERT_TRUE(samples);
  EXPECT_TRUE(samples->inputAttachment) << describe(four.graph, c4);
  EXPECT_FALSE(c4.attachment(0, four.hdr)->inputAttachment);
  EXPECT_TRUE(c4.traffic[four.hdrSamples].transient);
  EXPECT_TRUE(c4.traffic[four.depth].transient);
  EXPECT_EQ(samples->store, StoreOp::DontCare);
  EXPECT_EQ(c4.loadedBytes(), c1.loadedBytes());
  EXPECT_EQ(c4.storedBytes(), c1.storedBytes());
  EXPECT_EQ(c4.sampledBytes(), c1.sampledBytes());
  const ForwardPostGraph readBack =
      buildForwardPostGraph(kW, kH, PostPath::Merged, true, HdrFormat::Rgba16Float, 4, false, 1.0, 0, 0, true);
  const CompiledGraph cr = compileOrFail(readBack.graph);
  EXPECT_TRUE(cr.traffic[readBack.hdrSamples].transient);
  EXPECT_EQ(cr.storedBytes(), c1.storedBytes() + kPixels * 8);
  const ForwardPostGraph separate =
      buildForwardPostGraph(kW, kH, PostPath::Separate, false, HdrFormat::Rgba16Float, 4, false, 1.0, 0, 0, true);
  const CompiledGraph cs = compileOrFail(separate.graph);
  EXPECT_TRUE(cs.traffic[separate.hdrSamples].transient);
  EXPECT_FALSE(cs.traffic[separate.hdr].transient);
}

// FXAA reads neighbouring pixels, so the tone-mapped image cannot stay in tile memory: it is
// stored once and sampled once (4 + 4 bytes a pixel more than without FXAA on either path), and
// the FXAA pass is a render pass of its own. Off, the graph has no such pass and no such image.
TEST(FrameGraph, FxaaStoresAndSamplesTheToneMappedImageAndNothingWhenOff) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(toString(path));
    const ForwardPostGraph off = buildForwardPostGraph(kW, kH, path, false);
    const ForwardPostGraph on = buildForwardPostGraph(kW, kH, path, false, HdrFormat::Rgba16Float, 1, true);
    EXPECT_EQ(off.fxaaPass, UINT32_MAX);
    EXPECT_EQ(off.toneMapped, off.ldr);
    EXPECT_EQ(off.graph.passCount(), 2u);
    EXPECT_EQ(off.graph.resourceCount(), 3u);
    const CompiledGraph c0 = compileOrFail(off.graph);
    const CompiledGraph c1 = compileOrFail(on.graph);
    ASSERT_EQ(c1.renderPasses.size(), c0.renderPasses.size() + 1) << describe(on.graph, c1);
    EXPECT_EQ(c1.renderPasses.back().subpasses, std::vector<uint32_t>{on.fxaaPass});
    const uint32_t postRenderPass = uint32_t(c1.renderPasses.size() - 2);
    const Attachment* toneMapped = c1.attachment(postRenderPass, on.toneMapped);
    ASSERT_NE(toneMapped, nullptr);
    EXPECT_EQ(toneMapped->store, StoreOp::Store);
    EXPECT_EQ(c1.attachment(postRenderPass, on.ldr), nullptr);
    EXPECT_EQ(c1.traffic[on.toneMapped].storedBytes, kPixels * 4);
    EXPECT_EQ(c1.traffic[on.toneMapped].sampledBytes, kPixels * 4);
    EXPECT_EQ(c1.storedBytes(), c0.storedBytes() + kPixels * 4);
    EXPECT_EQ(c1.sampledBytes(), c0.sampledBytes() + kPixels * 4);
    EXPECT_EQ(c1.traffic[on.hdr].transient, c0.traffic[off.hdr].transient);
    EXPECT_NE(describe(on.graph, c1).find("fxaa"), std::string::npos);
  }
}

// Off, nothing of bloom exists and the merged path stores only the LDR image (HDR and depth
// transient). On, HDR is stored and sampled by the chain's first downsample and by the post pass
// (the path is the separate one), and each level is stored after its downsample, loaded and stored
// again by its upsample (all but the coarsest) and sampled by the next pass.
TEST(FrameGraph, BloomStoresTheHdrImageAndTheChainAndNothingWhenOff) {
  const ForwardPostGraph off = buildForwardPostGraph(kW, kH, PostPath::Merged, false);
  const CompiledGraph c0 = compileOrFail(off.graph);
  EXPECT_TRUE(off.bloom.empty());
  ASSERT_EQ(c0.renderPasses.size(), 1u);
  EXPECT_EQ(c0.storedBytes(), kPixels * 4);
  EXPECT_EQ(c0.traffic[off.ldr].storedBytes, kPixels * 4);
  EXPECT_EQ(c0.loadedBytes(), 0u);
  EXPECT_EQ(c0.sampledBytes(), 0u);
  EXPECT_TRUE(c0.traffic[off.hdr].transient);
  EXPECT_TRUE(c0.traffic[off.depth].transient);

  const int levels = 5;
  const ForwardPostGraph on =
      buildForwardPostGraph(kW, kH, PostPath::Merged, false, HdrFormat::Rgba16Float, 1, false, 1.0, levels);
  const CompiledGraph c1 = compileOrFail(on.graph);
  const std::vector<ImageSize> sizes = bloomLevelSizes(kW, kH, levels);
  ASSERT_EQ(on.bloom.size(), size_t(levels));
  ASSERT_EQ(on.bloomUpPasses.size(), size_t(levels - 1));
  // forward, the downsamples, the upsamples, post: none merges (each samples the whole image before).
  EXPECT_EQ(c1.renderPasses.size(), size_t(2 * levels + 1)) << describe(on.graph, c1);
  EXPECT_FALSE(c1.traffic[on.hdr].transient);
  EXPECT_EQ(c1.traffic[on.hdr].storedBytes, kPixels * 8);
  EXPECT_EQ(c1.traffic[on.hdr].sampledBytes, 2 * kPixels * 8);  // the first downsample and the post pass
  uint64_t chainStored = 0, chainLoaded = 0, chainSampled = 0;
  for (int i = 0; i < levels; ++i) {
    const uint64_t bytes = uint64_t(sizes[size_t(i)].width) * sizes[size_t(i)].height * 8;
    const ResourceTraffic& t = c1.traffic[on.bloom[size_t(i)]];
    const bool blended = i + 1 < levels;  // every level but the coarsest gets an upsample
    EXPECT_EQ(t.storedBytes, bytes * (blended ? 2 : 1)) << i;
    EXPECT_EQ(t.loadedBytes, blended ? bytes : 0) << i;
    // Sampled by the next downsample and by the finer level's upsample; level 0 by the post pass.
    EXPECT_EQ(t.sampledBytes, bytes * ((i + 1 < levels ? 1 : 0) + 1)) << i;
    chainStored += t.storedBytes;
    chainLoaded += t.loadedBytes;
    chainSampled += t.sampledBytes;
  }
  EXPECT_EQ(c1.storedBytes(), kPixels * 4 + kPixels * 8 + chainStored);
  EXPECT_EQ(c1.loadedBytes(), chainLoaded);
  EXPECT_EQ(c1.sampledBytes(), 2 * kPixels * 8 + chainSampled);
  EXPECT_EQ(sizes[0].width, (kW + 1) / 2);
  EXPECT_NE(describe(on.graph, c1).find("bloom_up0"), std::string::npos);
}

TEST(FrameGraph, BloomLevelsStopAtTheFirstImagesMipCount) {
  // 317 × 199: image 0 is 159 × 100, then 80 × 50, 40 × 25, 20 × 13, 10 × 7, 5 × 4, 3 × 2, 2 × 1, 1 × 1.
  const std::vector<ImageSize> odd = bloomLevelSizes(317, 199, 12);
  ASSERT_EQ(odd.size(), 9u);
  EXPECT_EQ(odd[0].width, 159u);
  EXPECT_EQ(odd[0].height, 100u);
  EXPECT_EQ(odd[3].width, 20u);
  EXPECT_EQ(odd[3].height, 13u);
  EXPECT_EQ(odd.back().width, 1u);
  EXPECT_EQ(odd.back().height, 1u);
  EXPECT_EQ(bloomLevelSizes(317, 199, 4).size(), 4u);
  EXPECT_EQ(bloomLevelSizes(1, 1, 6).size(), 1u);
  EXPECT_EQ(bloomLevelSizes(5, 3, 6).size(), 3u);  // 3 × 2, 2 × 1, 1 × 1
  const ForwardPostGraph tiny =
      buildForwardPostGraph(5, 3, PostPath::Separate, false, HdrFormat::Rgba16Float, 1, false, 1.0, 6);
  EXPECT_EQ(tiny.bloom.size(), 3u);
  compileOrFail(tiny.graph);
}

TEST(FrameGraph, ShadowMapIsStoredAndDoesNotMerge) {
  FrameGraph graph;
  const ResourceId shadow = graph.addResource({"shadow", 2048, 2048, 4, true, false});
  const ResourceId hdr = graph.addResource({"hdr", kW, kH, 8, false, false});
  const ResourceId depth = graph.addResource({"depth", kW, kH, 4, true, false});
  const ResourceId ldr = graph.addResource({"ldr", kW, kH, 4, false, true});
  const uint32_t shadowPass = graph.addPass({"shadow", {}, {shadow}, {shadow}});
  const uint32_t forward = graph.addPass({"forward", {{shadow, ReadKind::WholeTexture}}, {hdr, depth}, {hdr, depth}});
  const uint32_t post = graph.addPass({"post", {{hdr, ReadKind::OwnPixel}}, {ldr}, {}});
  const CompiledGraph c = compileOrFail(graph);
  ASSERT_EQ(c.renderPasses.size(), 2u) << describe(graph, c);
  EXPECT_EQ(c.renderPasses[0].subpasses, std::vector<uint32_t>{shadowPass});
  EXPECT_EQ(c.renderPasses[1].subpasses, (std::vector<uint32_t>{forward, post}));
  EXPECT_EQ(c.attachment(0, shadow)->load, LoadOp::Clear);
  EXPECT_EQ(c.attachment(0, shadow)->store, StoreOp::Store);  // sampled by the forward pass
  EXPECT_FALSE(c.traffic[shadow].transient);
  EXPECT_EQ(c.traffic[shadow].storedBytes, 2048u * 2048 * 4);
  EXPECT_EQ(c.traffic[shadow].sampledBytes, 2048u * 2048 * 4);
  EXPECT_EQ(c.attachment(1, hdr)->store, StoreOp::DontCare);
  EXPECT_EQ(c.attachment(1, depth)->store, StoreOp::DontCare);
}

TEST(FrameGraph, BloomDownsampleChainSamplesWholeTexturesAndDoesNotMerge) {
  FrameGraph graph;
  const ResourceId hdr = graph.addResource({"hdr", kW, kH, 8, false, false});
  const ResourceId depth = graph.addResource({"depth", kW, kH, 4, true, false});
  const ResourceId half = graph.addResource({"bloom/2", kW / 2, kH / 2, 8, false, false});
  const ResourceId quarter = graph.addResource({"bloom/4", kW / 4, kH / 4, 8, false, false});
  const ResourceId ldr = graph.addResource({"ldr", kW, kH, 4, false, true});
  graph.addPass({"forward", {}, {hdr, depth}, {hdr, depth}});
  graph.addPass({"down2", {{hdr, ReadKind::WholeTexture}}, {half}, {}});
  graph.addPass({"down4", {{half, ReadKind::WholeTexture}}, {quarter}, {}});
  graph.addPass({"post", {{hdr, ReadKind::OwnPixel}, {quarter, ReadKind::WholeTexture}}, {ldr}, {}});
  const CompiledGraph c = compileOrFail(graph);
  ASSERT_EQ(c.renderPasses.size(), 4u) << describe(graph, c);
  for (const RenderPass& rp : c.renderPasses) EXPECT_EQ(rp.subpasses.size(), 1u);
  EXPECT_EQ(c.attachment(0, hdr)->store, StoreOp::Store);
  EXPECT_EQ(c.attachment(0, depth)->store, StoreOp::DontCare);
  EXPECT_EQ(c.attachment(1, half)->store, StoreOp::Store);
  EXPECT_EQ(c.attachment(2, quarter)->store, StoreOp::Store);
  EXPECT_EQ(c.attachment(1, half)->load, LoadOp::DontCare);  // fully written, never cleared
  // hdr is sampled twice: by the downsample and, from memory, by the post pass.
  EXPECT_EQ(c.traffic[hdr].sampledBytes, 2 * kPixels * 8);
}

// The sun's shadow pass: its own render pass before the forward one, which samples the atlas
// whole; the forward and post passes still merge. The atlas's bytes are stored once and sampled
// once per frame (docs/shadows.md, "Shadow pass").
TEST(FrameGraph, TheShadowAtlasIsStoredAndSampledByTheForwardPass) {
  constexpr uint32_t kAtlas = 2048;
  constexpr uint64_t kAtlasBytes = uint64_t{kAtlas} * kAtlas * kShadowAtlasBytesPerTexel;
  ForwardPostGraph g =
      buildForwardPostGraph(kW, kH, PostPath::Merged, false, HdrFormat::Rgba16Float, 1, false, 1.0, 0, kAtlas);
  const CompiledGraph c = compileOrFail(g.graph);
  ASSERT_EQ(c.renderPasses.size(), 2u) << describe(g.graph, c);
  EXPECT_EQ(c.renderPasses[0].subpasses, (std::vector<uint32_t>{g.shadowPass}));
  EXPECT_EQ(c.renderPasses[1].subpasses, (std::vector<uint32_t>{g.forwardPass, g.postPass}));
  const Attachment* atlas = c.attachment(0, g.shadowAtlas);
  ASSERT_TRUE(atlas);
  EXPECT_EQ(atlas->load, LoadOp::Clear);
  EXPECT_EQ(atlas->store, StoreOp::Store);
  EXPECT_EQ(c.attachment(1, g.shadowAtlas), nullptr);
  EXPECT_EQ(c.traffic[g.shadowAtlas].storedBytes, kAtlasBytes);
  EXPECT_EQ(c.traffic[g.shadowAtlas].sampledBytes, kAtlasBytes);
  EXPECT_EQ(c.traffic[g.shadowAtlas].loadedBytes, 0u);
  EXPECT_TRUE(c.traffic[g.hdr].transient);
  EXPECT_EQ(c.storedBytes(), kPixels * 4 + kAtlasBytes);
  EXPECT_NE(describe(g.graph, c).find("  shadow     loaded          0 B  stored    8388608 B  sampled    8388608 B"),
            std::string::npos)
      << describe(g.graph, c);
  // Without a shadow: no such pass or image.
  const ForwardPostGraph none = buildForwardPostGraph(kW, kH, PostPath::Merged, false);
  EXPECT_EQ(none.shadowPass, UINT32_MAX);
  EXPECT_EQ(none.graph.resourceCount(), g.graph.resourceCount() - 1);
}

TEST(FrameGraph, PassesWhoseOutputsNobodyReadsAreCulled) {
  ForwardPostGraph g = buildForwardPostGraph(kW, kH, PostPath::Merged, false);
  const ResourceId debug = g.graph.addResource({"debug", kW, kH, 4, false, false});
  const uint32_t debugPass = g.graph.addPass({"debug", {{g.hdr, ReadKind::WholeTexture}}, {debug}, {}});
  const CompiledGraph c = compileOrFail(g.graph);
  EXPECT_TRUE(c.culled[debugPass]);
  EXPECT_FALSE(c.culled[g.forwardPass]);
  ASSERT_EQ(c.renderPasses.size(), 1u) << describe(g.graph, c);
  // The culled pass's sampling does not force HDR to memory.
  EXPECT_EQ(c.attachment(0, g.hdr)->store, StoreOp::DontCare);
  EXPECT_EQ(c.traffic[debug].storedBytes, 0u);
}

TEST(FrameGraph, WritingWithoutClearAfterAnEarlierRenderPassLoads) {
  FrameGraph graph;
  const ResourceId colour = graph.addResource({"colour", 16, 16, 4, false, true});
  const ResourceId other = graph.addResource({"other", 8, 8, 4, false, false});
  graph.addPass({"base", {}, {colour}, {colour}});
  graph.addPass({"other", {{colour, ReadKind::WholeTexture}}, {other}, {other}});
  graph.addPass({"overlay", {{other, ReadKind::WholeTexture}}, {colour}, {}});
  const CompiledGraph c = compileOrFail(graph);
  ASSERT_EQ(c.renderPasses.size(), 3u) << describe(graph, c);
  EXPECT_EQ(c.attachment(2, colour)->load, LoadOp::Load);
  EXPECT_EQ(c.traffic[colour].loadedBytes, 16u * 16 * 4);
}

TEST(FrameGraph, ReadingBeforeAnyWriteIsAnError) {
  FrameGraph graph;
  const ResourceId a = graph.addResource({"a", 4, 4, 4, false, true});
  graph.addPass({"p", {{a, ReadKind::OwnPixel}}, {a}, {}});
  CompiledGraph c;
  std::string error;
  EXPECT_FALSE(graph.compile(&c, &error));
  EXPECT_NE(error.find("before any pass writes it"), std::string::npos) << error;
  FrameGraph bad;
  bad.addPass({"q", {}, {7}, {}});
  EXPECT_FALSE(bad.compile(&c, &error));
  EXPECT_NE(error.find("unknown resource"), std::string::npos) << error;
}

}  // namespace
