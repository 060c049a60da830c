// The vertex's world position, highp, in statements (included inside main): the one text the
// forward vertex stage (templates/forward.vert.glsl) and the shadow pass's depth-only program
// (templates/depth.vert.glsl) both run, so the depths the shadow atlas stores and the receivers'
// positions come from the same arithmetic.
    // The position stream may hold 16-bit normalized values over the mesh's bounds
    // (runtime/vertex_packing.h): one FMA decodes them to object space, in highp (fp32: the
    // 16-bit step is extent / 65534, far above fp32's rounding). fp32 streams get scale 1, offset 0.
    highp vec3 position = a_position * object.positionScale.xyz + object.positionOffset.xyz;
    // The instance's 4×3 transform (shader_abi.h InstanceTransform): three rows, one dot each.
    highp vec4 objectPosition = vec4(position, 1.0);
    highp vec4 worldPosition = vec4(dot(a_instanceRow0, objectPosition), dot(a_instanceRow1, objectPosition),
                                    dot(a_instanceRow2, objectPosition), 1.0);
