// The shadow receiver axes of variant keys (docs/permutations.md), the sun's and a spot's: their string form, the key a
// scene asks for, and what gets built with and without a scene.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "facet/permutations/variant_key.h"

namespace {

using facet::permutations::enumerate;
using facet::permutations::requestKey;
using facet::permutations::SceneNeeds;
using facet::permutations::Tier;
using facet::permutations::VariantKey;

std::vector<std::string> names(const std::vector<VariantKey>& keys) {
  std::vector<std::string> out;
  for (const VariantKey& k : keys) out.push_back(k.toString());
  return out;
}

}  // namespace

TEST(ShadowKeys, ThreeCascadesUseTheFourCascadeReceiver) {
  EXPECT_EQ(facet::permutations::shadowCascadePermutation(0), 0);
  EXPECT_EQ(facet::permutations::shadowCascadePermutation(1), 1);
  EXPECT_EQ(facet::permutations::shadowCascadePermutation(3), 4);
  EXPECT_EQ(facet::permutations::shadowCascadePermutation(5), std::nullopt);
  EXPECT_EQ(requestKey({true}, Tier::High, true, 0, 3).toString(), "high.dir1.sh4");
  EXPECT_EQ(requestKey({true}, Tier::Low, true, 2, 1).toString(), "low.dir1.sh1.pt2");
  // No sun, no shadow; an unlit material receives nothing.
  EXPECT_EQ(requestKey({true}, Tier::Mid, false, 1, 2).toString(), "mid.dir0.pt1");
  EXPECT_EQ(requestKey({false}, Tier::Mid, true, 1, 2).toString(), "mid.dir0");
}

TEST(ShadowKeys, KeysRoundTripAndMalformedOnesAreRefused) {
  for (const char* text : {"high.dir1.sh1", "mid.dir1.sh2.pt1", "reference.dir1.sh4.pt4", "low.dir1.pt2"}) {
    auto key = VariantKey::parse(text);
    ASSERT_TRUE(key) << text;
    EXPECT_EQ(key->toString(), text);
  }
  EXPECT_EQ(VariantKey::parse("high.dir1.sh2")->shadowCascades, 2);
  // sh3 is not a permutation; shadows need the sun; the fields have one order.
  for (const char* bad : {"high.dir1.sh3", "high.dir1.sh0", "high.dir0.sh1", "high.dir1.pt1.sh1", "high.dir1.sh1.sh1",
                          "high.dir1.sh1.pt1.x"})
    EXPECT_FALSE(VariantKey::parse(bad)) << bad;
}

// Today's default output does not grow: receivers are built only when asked for.
TEST(ShadowKeys, ReceiversAreBuiltOnlyWhenAskedFor) {
  EXPECT_EQ(names(enumerate({true}, {Tier::High})), (std::vector<std::string>{"high.dir0", "high.dir1"}));
  // With the tier's depth-only program for the shadow pass (test_depth_programs.cpp).
  EXPECT_EQ(names(enumerate({true}, {Tier::High}, nullptr, {0}, {0, 1, 2, 4})),
            (std::vector<std::string>{"high.dir0", "high.dir1", "high.dir1.sh1", "high.dir1.sh2", "high.dir1.sh4",
                                      "high.depth"}));
  EXPECT_EQ(names(enumerate({false}, {Tier::High}, nullptr, {0}, {0, 1, 2, 4})),
            (std::vector<std::string>{"high.dir0", "high.depth"}));
  const SceneNeeds scene{{requestKey({true}, Tier::Mid, true, 0, 2), requestKey({true}, Tier::Mid, true, 0, 0)}};
  EXPECT_EQ(names(enumerate({true}, {Tier::Mid, Tier::High}, &scene)),
            (std::vector<std::string>{"mid.dir1", "mid.dir1.sh2"}));
}

// The spot-shadow axis (docs/shadows.md, "Spot shadows"): `.sp1` after a point-light field only,
// light slot 0 the casting spot; an unlit material or a variant without point lights has none.
TEST(ShadowKeys, TheSpotShadowAxisFollowsThePointLights) {
  EXPECT_EQ(requestKey({true}, Tier::High, false, 1, 0, true).toString(), "high.dir0.pt1.sp1");
  EXPECT_EQ(requestKey({true}, Tier::Low, true, 3, 2, true).toString(), "low.dir1.sh2.pt4.sp1");
  EXPECT_EQ(requestKey({true}, Tier::Mid, true, 0, 1, true).toString(), "mid.dir1.sh1");
  EXPECT_EQ(requestKey({false}, Tier::Mid, false, 1, 0, true).toString(), "mid.dir0");
  EXPECT_TRUE(requestKey({true}, Tier::High, false, 1, 0, true).receivesShadow());
  EXPECT_FALSE(requestKey({true}, Tier::High, false, 1, 0, false).receivesShadow());
  for (const char* text : {"high.dir0.pt1.sp1", "mid.dir1.sh4.pt2.sp1", "low.dir1.pt4.sp1"}) {
    auto key = VariantKey::parse(text);
    ASSERT_TRUE(key) << text;
    EXPECT_EQ(key->toString(), text);
    EXPECT_EQ(key->spotShadows, 1) << text;
  }
  // Only one spot casts; it needs a punctual light; the fields have one order.
  for (const char* bad : {"high.dir0.pt1.sp2", "high.dir0.pt1.sp0", "high.dir0.sp1", "high.dir1.sh1.sp1",
                          "high.dir0.sp1.pt1", "high.dir0.pt1.sp1.sp1", "high.dir1.sh1.pt1.sp1.x"})
    EXPECT_FALSE(VariantKey::parse(bad)) << bad;
}

TEST(ShadowKeys, SpotReceiversAreBuiltOnlyWhenAskedFor) {
  EXPECT_EQ(names(enumerate({true}, {Tier::High}, nullptr, {0, 1})),
            (std::vector<std::string>{"high.dir0", "high.dir0.pt1", "high.dir1", "high.dir1.pt1"}));
  EXPECT_EQ(names(enumerate({true}, {Tier::High}, nullptr, {0, 1}, {0}, true)),
            (std::vector<std::string>{"high.dir0", "high.dir0.pt1", "high.dir0.pt1.sp1", "high.dir1", "high.dir1.pt1",
                                      "high.dir1.pt1.sp1", "high.depth"}));
  // An unlit material has no lights to shadow; it still casts.
  EXPECT_EQ(names(enumerate({false}, {Tier::High}, nullptr, {0, 1}, {0}, true)),
            (std::vector<std::string>{"high.dir0", "high.depth"}));
  const SceneNeeds scene{{requestKey({true}, Tier::Mid, false, 1, 0, true)}};
  EXPECT_EQ(names(enumerate({true}, {Tier::Mid, Tier::High}, &scene)), (std::vector<std::string>{"mid.dir0.pt1.sp1"}));
}
