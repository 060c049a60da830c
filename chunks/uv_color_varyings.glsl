// The UV sets and the vertex colour as the fragment stage reads them, in statements (included
// inside main, after chunks/object_to_world.glsl): the forward vertex stage and the depth-only
// program (a masked material's alpha) decode them alike. UVs: unorm16 over the UV set's bounds,
// one FMA each (scale in xy, offset in zw).
#if defined(FACET_VARYING_UV0)
    v_uv0 = a_uv0 * object.uv0ScaleOffset.xy + object.uv0ScaleOffset.zw;
#endif
#if defined(FACET_VARYING_UV1)
    v_uv1 = a_uv1 * object.uv1ScaleOffset.xy + object.uv1ScaleOffset.zw;
#endif
#if defined(FACET_VARYING_COLOR)
    v_color = a_color;
#endif
