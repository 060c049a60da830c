#version 300 es
precision mediump float;
precision highp int;
in mediump vec3 v_toEye;
in mediump vec3 v_normal;
in highp vec2 v_uv0;
in mediump vec4 v_tangent;
in mediump vec3 v_diffuseLight;
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
mediump vec3 tint;
mediump float tiling;
mediump float roughness;
mediump float facet_pad20;
mediump float facet_pad24;
mediump float facet_pad28;
mediump vec3 facet_diffuseColor;
mediump float facet_perceptualRoughness;
mediump vec3 facet_f0;
mediump float facet_alpha;
mediump float facet_environmentLod;
mediump float facet_ggxAlphaScaled;
mediump float facet_ziomaRoughnessFactor;
}
params;
uniform mediump sampler2D facet_material_ripples;
uniform mediump samplerCube facet_environment;
uniform mediump sampler2D facet_dfgLut;
const float MIN_PERCEPTUAL_ROUGHNESS=0.089;
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
return m;
}
vec3 shading_normal;
vec3 shading_view;
void evaluate_surface(inout MaterialInputs material){
material.baseColor=params.tint;
material.roughness=params.roughness;
highp vec2 t0=v_uv0*params.tiling;
vec3 t1=texture(facet_material_ripples,t0).xyz*(255.0/127.0)-(128.0/127.0);
material.normal=t1;
}
vec3 tangent_to_world(vec3 tangentNormal){
vec3 n=v_normal;
vec3 t=v_tangent.xyz;
if(dot(t,t)==0.0)return normalize(n);
vec3 b=v_tangent.w*cross(n,t);
return normalize(tangentNormal.x*t+tangentNormal.y*b+tangentNormal.z*n);
}
float ggx_d_scaled(float alpha,float NoH,vec3 n,vec3 h){
vec4 t=64.0*vec4(cross(n,h),alpha*NoH);
return dot(t,t);
}
const float FUSED_HAMMON_M_MIN=2.44140625e-4;
float specular_fused_hammon(float alpha,float NoV,float NoL,float NoH,vec3 n,vec3 h){
float d=ggx_d_scaled(alpha,NoH,n,h);
float m=max(mix(2.0*NoL*NoV,NoL+NoV,alpha),FUSED_HAMMON_M_MIN);
float k=(4096.0*alpha)/(d*((2.0*3.14159265359)*m));
return min(k*(k*((2.0*3.14159265359)*m)),65504.0);
}
vec3 specular_lobe(float perceptualRoughness,float alpha,float NoV,float NoL,float NoH,float LoH,vec3 n,vec3 v,vec3 l,vec3 h,vec3 f0){
return specular_fused_hammon(alpha,NoV,NoL,NoH,n,h)*f0;
}
vec3 prefiltered_radiance(vec3 direction,float r){
return textureLod(facet_environment,direction,r*(float(5-1)*(2.0-r))).rgb;
}
vec2 dfg_terms(float NoV,float perceptualRoughness){
return textureLod(facet_dfgLut,vec2(NoV,perceptualRoughness),0.0).rg;
}
vec3 split_sum_albedo(vec2 dfg,vec3 f0){
return mix(dfg.xxx,dfg.yyy,f0);
}
vec3 material_diffuse_color(MaterialInputs material){
return params.facet_diffuseColor;
}
vec3 material_f0(MaterialInputs material){
return params.facet_f0;
}
float material_perceptual_roughness(MaterialInputs material){
return clamp(material.roughness,MIN_PERCEPTUAL_ROUGHNESS,1.0);
}
float material_alpha(MaterialInputs material){
float perceptualRoughness=material_perceptual_roughness(material);
return perceptualRoughness*perceptualRoughness;
}
vec3 half_vector(vec3 v,vec3 l){
return normalize(v+l);
}
vec3 shade_standard_direct(MaterialInputs material,vec3 n,highp vec3 viewHighp,highp vec3 lightHighp,vec3 lightColor){
vec3 f0=material_f0(material);
float perceptualRoughness=material_perceptual_roughness(material);
float alpha=material_alpha(material);
vec3 v=viewHighp;
vec3 l=lightHighp;
float NoV=max(dot(n,v),MIN_N_DOT_V);
float NoL=clamp(dot(n,l),0.0,1.0);
vec3 h=half_vector(v,l);
float NoH=clamp(dot(n,h),0.0,1.0);
float LoH=clamp(dot(l,h),0.0,1.0);
vec3 specular=specular_lobe(perceptualRoughness,alpha,NoV,NoL,NoH,LoH,n,v,l,h,f0);
vec3 irradiance=lightColor*NoL;
return min(specular*irradiance,65504.0);
}
float specular_aa_roughness(float perceptualRoughness,vec3 normal){
highp vec3 du=dFdx(normal);
highp vec3 dv=dFdy(normal);
highp float variance=0.02*(dot(du,du)+dot(dv,dv));
highp float alpha=perceptualRoughness*perceptualRoughness;
highp float kernel=min(2.0*variance,0.2);
return sqrt(sqrt(min(alpha*alpha+kernel,1.0)));
}
vec3 apply_ambient_occlusion(MaterialInputs material,vec3 ambient){
return ambient;
}
vec3 shade_standard_ambient_specular(MaterialInputs material,vec3 n,vec3 v){
vec3 f0=material_f0(material);
float perceptualRoughness=material_perceptual_roughness(material);
float NoV=max(dot(n,v),MIN_N_DOT_V);
vec3 r=reflect(-v,n);
vec2 dfg=dfg_terms(NoV,perceptualRoughness);
vec3 albedo=split_sum_albedo(dfg,f0);
vec3 specular=prefiltered_radiance(r,perceptualRoughness);
return apply_ambient_occlusion(material,specular*albedo);
}
vec3 add_light(vec3 color,vec3 radiance){
return color+radiance;
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
shading_normal=tangent_to_world(material.normal);
material.roughness=specular_aa_roughness(material_perceptual_roughness(material),shading_normal);
vec3 color=apply_ambient_occlusion(material,material_diffuse_color(material)*v_diffuseLight);
color=linear_from_shading_space(color);
color=add_light(color,shade_standard_ambient_specular(material,shading_normal,shading_view));
highp vec3 l=frame.lightDirection.xyz;
color=add_light(color,shade_standard_direct(material,shading_normal,shading_view_for_lights,l,frame.lightColor.rgb));
fragColor=blend_output(add_light(color,linear_from_shading_space(material.emissive)),material.alpha);
}
