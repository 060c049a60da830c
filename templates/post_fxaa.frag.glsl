// FXAA pass fragment stage: the tone-mapped LDR image of the post pass, sampled (bilinear,
// clamped) because FXAA reads neighbouring pixels, anti-aliased by chunks/fxaa.glsl into the
// RGBA8 output. Assembled by the compiler's post domain (compiler/src/post.cpp), which declares
// `toneMapped` and `fragColor` from shader_abi.h. Each API's window origin matches its own
// texture row 0 (as in post_tonemap.frag.glsl), so gl_FragCoord addresses the texel it covers.
void main() {
    highp vec2 texel = 1.0 / vec2(textureSize(toneMapped, 0));
    highp vec2 uv = gl_FragCoord.xy * texel;
    fragColor = vec4(fxaa_console(toneMapped, ivec2(gl_FragCoord.xy), uv, texel), 1.0);
}
