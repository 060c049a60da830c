#version 300 es
// Test pair for tests/gpu_stats/test_mesa_stats_compile.py: a transform and one varying.
layout(location = 0) in highp vec3 a_position;
uniform highp mat4 u_mvp;
out mediump vec2 v_uv;
void main() {
    v_uv = a_position.xy * 0.5 + 0.5;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
