// Bloom downsample pass (chunks/bloom.glsl): the finer image `bloomSource` (the HDR image for the
// first level) filtered by the 13-tap downsample into the next level; FACET_BLOOM_THRESHOLD (first
// level, a threshold set) keeps only its bright part. Assembled by the compiler's post domain
// (compiler/src/post.cpp), which declares `bloomSource`, `fragColor` and the PostUniforms block.
#ifdef FACET_VULKAN
layout(location = 0) in highp vec2 bloomUv;
#else
in highp vec2 bloomUv;
#endif

void main() {
    highp vec2 texel = 1.0 / vec2(textureSize(bloomSource, 0));
    vec3 colour = bloom_downsample13(bloomSource, bloomUv, texel);
#if defined(FACET_BLOOM_THRESHOLD)
    colour = bloom_bright(colour, post.bloom.y, post.bloom.z);
#endif
    fragColor = vec4(colour, 1.0);
}
