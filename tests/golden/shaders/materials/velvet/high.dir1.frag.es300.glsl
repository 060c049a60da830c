#version 300 es
precision mediump float;
precision highp int;
in mediump vec3 v_toEye;
in mediump vec3 v_normal;
layout(location=0)out mediump vec4 fragColor;
struct PunctualLightData{
highp vec4 positionFalloff;
highp vec4 colorIntensity;
highp vec4 direction;
highp vec4 spotScaleOffset;
};
layout(std140)uniform FrameUniforms{
highp mat4 viewProjection;
highp vec4 cameraPosition;
highp vec4 lightDirection;
highp vec4 lightColor;
highp vec4 ambient;
PunctualLightData punctualLights[4];
highp vec4 sh[9];
}
frame;
layout(std140)uniform MaterialParams{
mediump vec3 fabric;
mediump vec3 sheen;
mediump float roughness;
mediump vec3 subsurface;
mediump float facet_pad44;
mediump vec3 facet_diffuseColor;
mediump float facet_perceptualRoughness;
mediump float facet_alpha;
mediump float facet_environmentLod;
mediump float facet_ggxAlphaScaled;
mediump float facet_ziomaRoughnessFactor;
mediump vec3 facet_sheenColor;
mediump float facet_sheenLod;
}
params;
uniform mediump samplerCube facet_environment;
uniform mediump sampler2D facet_dfgLut;
uniform mediump samplerCube facet_irradiance;
const float MIN_N_DOT_V=1e-4;
const float VIEW_VECTOR_MIN_SQUARE=6.103515625e-05;
vec3 view_direction(vec3 scaledToEye){
return scaledToEye*inversesqrt(max(dot(scaledToEye,scaledToEye),VIEW_VECTOR_MIN_SQUARE));
}
struct MaterialInputs{
vec3 baseColor;
float alpha;
float metallic;
float roughness;
float reflectance;
vec3 normal;
vec3 emissive;
float ambientOcclusion;
vec3 sheenColor;
vec3 subsurfaceColor;
};
MaterialInputs material_defaults(){
MaterialInputs m;
m.baseColor=vec3(1.0);
m.alpha=1.0;
m.metallic=0.0;
m.roughness=1.0;
m.reflectance=0.5;
m.normal=vec3(0.0,0.0,1.0);
m.emissive=vec3(0.0);
m.ambientOcclusion=1.0;
m.sheenColor=vec3(0.0);
m.subsurfaceColor=vec3(0.0);
return m;
}
vec3 shading_normal;
vec3 shading_view;
void evaluate_surface(inout MaterialInputs material){
material.baseColor=params.fabric;
material.roughness=params.roughness;
material.sheenColor=params.sheen;
material.subsurfaceColor=params.subsurface;
}
float diffuse_lambert(){
return 0.31830988618;
}
vec3 cube_irradiance_over_pi(vec3 n){
return textureLod(facet_irradiance,n,0.0).rgb;
}
float sheen_lobe_times_n_dot_l(float alpha,float NoV,float NoL,float NoH){
float scaledQ=8192.0*(NoL+NoV-NoL*NoV);
float k=1.0/(alpha*scaledQ);
float invAlpha=k*scaledQ;
float visibilityTimesNoL=NoL*(k*(2048.0*alpha));
float sin2h=max(1.0-NoH*NoH,0.0);
return(2.0+invAlpha)*pow(sin2h,0.5*invAlpha)*(0.5*0.31830988618)*visibilityTimesNoL;
}
vec3 shading_sheen_color=vec3(0.0);
float shading_sheen_alpha=1.0;
float shading_sheen_scale=1.0;
float shading_sheen_base_scale=1.0;
vec3 sheen_light(float NoV,float NoL,float NoH){
return shading_sheen_color*(sheen_lobe_times_n_dot_l(shading_sheen_alpha,NoV,NoL,NoH)*shading_sheen_scale);
}
vec3 material_diffuse_color(MaterialInputs material){
return params.facet_diffuseColor;
}
float material_perceptual_roughness(MaterialInputs material){
return params.facet_perceptualRoughness;
}
float material_alpha(MaterialInputs material){
return params.facet_alpha;
}
vec3 half_vector(vec3 v,vec3 l){
return normalize(v+l);
}
vec3 apply_ambient_occlusion(MaterialInputs material,vec3 ambient){
return ambient;
}
vec3 shade_standard_ambient(MaterialInputs material,vec3 irradianceOverPi){
return apply_ambient_occlusion(material,material_diffuse_color(material)*irradianceOverPi);
}
vec3 add_light(vec3 color,vec3 radiance){
return color+radiance;
}
vec3 sheen_color(MaterialInputs material){
return params.facet_sheenColor;
}
float sheen_perceptual_roughness(MaterialInputs material){
return material_perceptual_roughness(material);
}
float sheen_alpha(MaterialInputs material){
return material_alpha(material);
}
vec3 sheen_layer(MaterialInputs material,vec3 base,vec3 n,vec3 v){
float perceptualRoughness=sheen_perceptual_roughness(material);
float NoV=max(dot(n,v),MIN_N_DOT_V);
vec2 sheenTerms=textureLod(facet_dfgLut,vec2(NoV,perceptualRoughness),0.0).ba;
vec3 sheenColor=sheen_color(material);
float baseScale=1.0-max(sheenColor.r,max(sheenColor.g,sheenColor.b))*sheenTerms.x;
shading_sheen_color=sheenColor;
shading_sheen_alpha=sheen_alpha(material);
shading_sheen_scale=sheenTerms.y;
shading_sheen_base_scale=baseScale;
vec3 radiance=textureLod(facet_environment,reflect(-v,n),params.facet_sheenLod).rgb;
vec3 specular=radiance*(sheenColor*sheenTerms.x);
return base*baseScale+specular;
}
vec3 shade_cloth_direct(MaterialInputs material,vec3 n,highp vec3 viewHighp,highp vec3 lightHighp,vec3 lightColor){
vec3 l=lightHighp;
float NoLSigned=dot(n,l);
float NoL=clamp(NoLSigned,0.0,1.0);
vec3 v=viewHighp;
vec3 h=half_vector(viewHighp,lightHighp);
float NoV=max(dot(n,v),MIN_N_DOT_V);
float NoH=clamp(dot(n,h),0.0,1.0);
vec3 sheen=sheen_light(NoV,NoL,NoH);
vec3 diffuseColor=material_diffuse_color(material);
vec3 diffuse=diffuseColor*(diffuse_lambert()*clamp((NoLSigned+0.5)*(1.0/2.25),0.0,1.0))*clamp(material.subsurfaceColor+NoL,0.0,1.0);
diffuse*=shading_sheen_base_scale;
return min((diffuse+sheen)*lightColor,65504.0);
}
vec3 linear_from_shading_space(vec3 color){
return color;
}
vec4 blend_output(vec3 color,float alpha){
return vec4(color,1.0);
}
vec3 shading_view_for_lights;
void main(){
shading_normal=normalize(v_normal);
shading_view_for_lights=view_direction(v_toEye);
shading_view=shading_view_for_lights;
MaterialInputs material=material_defaults();
evaluate_surface(material);
vec3 color=shade_standard_ambient(material,cube_irradiance_over_pi(shading_normal));
color=linear_from_shading_space(color);
color=sheen_layer(material,color,shading_normal,shading_view);
highp vec3 l=frame.lightDirection.xyz;
color=add_light(color,shade_cloth_direct(material,shading_normal,shading_view_for_lights,l,frame.lightColor.rgb));
fragColor=blend_output(add_light(color,linear_from_shading_space(material.emissive)),material.alpha);
}
