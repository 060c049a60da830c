#version 300 es
// One texture sample and nothing else: the texture pipe, no special-function ops.
precision mediump float;
in mediump vec2 v_uv;
uniform mediump sampler2D u_tex;
layout(location = 0) out mediump vec4 fragColor;
void main() {
    fragColor = texture(u_tex, v_uv);
}
