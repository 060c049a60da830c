// Bloom upsample pass (chunks/bloom.glsl): the coarser level `bloomSource` through the 3×3 tent,
// written over the finer level with the constant blend the runtime sets (weight 1 / (levels − i)
// for the finer level's own blur). Assembled by the compiler's post domain (compiler/src/post.cpp).
#ifdef FACET_VULKAN
layout(location = 0) in highp vec2 bloomUv;
#else
in highp vec2 bloomUv;
#endif

void main() {
    highp vec2 texel = 1.0 / vec2(textureSize(bloomSource, 0));
    fragColor = vec4(bloom_tent9(bloomSource, bloomUv, texel), 1.0);
}
