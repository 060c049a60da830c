#version 300 es
// The texture sample of texture.frag, plus pow and a division per channel: the same texture
// work and more arithmetic (pow = exp2(y * log2(x)): special-function ops).
precision mediump float;
in mediump vec2 v_uv;
uniform mediump sampler2D u_tex;
uniform mediump vec4 u_exponent;
layout(location = 0) out mediump vec4 fragColor;
void main() {
    mediump vec4 c = texture(u_tex, v_uv);
    fragColor = pow(c, u_exponent) / (c + u_exponent);
}
