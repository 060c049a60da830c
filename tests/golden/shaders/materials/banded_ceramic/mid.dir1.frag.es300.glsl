#version 300 es
precision mediump float;
precision highp int;
in highp vec3 v_worldPosition;
in mediump vec3 v_normal;
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
mediump vec3 glazeColor;
mediump vec3 clayColor;
mediump float glazeRoughness;
mediump float clayRoughness;
mediump float bandsPerUnit;
mediump float bandSharpness;
}
params;
uniform mediump samplerCube facet_environment;
uniform mediump sampler2D facet_dfgLut;
const float MIN_PERCEPTUAL_ROUGHNESS=0.089;
const float MIN_N_DOT_V=1e-4;
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
float t0= -params.bandSharpness;
highp float t1=v_worldPosition.y;
highp float t2=t1*params.bandsPerUnit;
highp float t3=t2*6.2831853;
highp float m_wave=sin(t3);
highp float m_glaze=smoothstep(t0,params.bandSharpness,m_wave);
highp vec3 t4=mix(params.clayColor,params.glazeColor,m_glaze);
material.baseColor=t4;
highp float t5=mix(params.clayRoughness,params.glazeRoughness,m_glaze);
material.roughness=t5;
highp float t6=mix(0.35,0.6,m_glaze);
material.reflectance=t6;
}
float ggx_d_scaled(float alpha,float NoH,vec3 n,vec3 h){
vec4 t=vec4(cross(n,h),alpha*NoH);
return dot(t,t);
}
const float ZIOMA_LOH2_MIN=0.15;
const float ZIOMA_ROUGH_SCALE= -0.3125;
const float ZIOMA_ROUGH_BIAS=1.0082;
float specular_zioma_kkx(float a,float d,float x){
float k=a/(d*x);
return min(k*k*x,65504.0);
}
float specular_zioma_form_d(float alpha,float d,float LoH,float loH2Min,float roughScale,float roughBias){
float x=(4.0*3.14159265359)*max(LoH*LoH,loH2Min)*(roughScale*alpha+roughBias);
return specular_zioma_kkx(alpha,d,x);
}
float specular_zioma_nxh(float alpha,float NoH,vec3 n,vec3 h,float LoH){
float d=ggx_d_scaled(alpha,NoH,n,h)*(1.0/4096.0);
return specular_zioma_form_d(alpha,d,LoH,ZIOMA_LOH2_MIN,ZIOMA_ROUGH_SCALE,ZIOMA_ROUGH_BIAS);
}
float specular_lobe_scalar(float alpha,float NoH,float LoH,vec3 n,vec3 h){
return specular_zioma_nxh(alpha,NoH,n,h,LoH);
}
vec3 specular_lobe(float perceptualRoughness,float alpha,float NoV,float NoL,float NoH,float LoH,vec3 n,vec3 v,vec3 l,vec3 h,vec3 f0){
return specular_lobe_scalar(alpha,NoH,LoH,n,h)*f0;
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
return(1.0-clamp(material.metallic,0.0,1.0))*clamp(material.baseColor,0.0,1.0);
}
vec3 material_f0(MaterialInputs material){
vec3 baseColor=clamp(material.baseColor,0.0,1.0);
float metallic=clamp(material.metallic,0.0,1.0);
float reflectance=clamp(material.reflectance,0.0,1.0);
return vec3(0.16*reflectance*reflectance*(1.0-metallic))+metallic*baseColor;
}
float material_perceptual_roughness(MaterialInputs material){
return clamp(material.roughness,MIN_PERCEPTUAL_ROUGHNESS,1.0);
}
float material_alpha(MaterialInputs material){
float perceptualRoughness=material_perceptual_roughness(material);
return perceptualRoughness*perceptualRoughness;
}
vec3 shade_standard_direct(MaterialInputs material,vec3 n,highp vec3 viewHighp,highp vec3 lightHighp,vec3 lightColor){
vec3 f0=material_f0(material);
float perceptualRoughness=material_perceptual_roughness(material);
float alpha=material_alpha(material);
vec3 v=viewHighp;
vec3 l=lightHighp;
float NoV=max(dot(n,v),MIN_N_DOT_V);
float NoL=clamp(dot(n,l),0.0,1.0);
vec3 h=(v+l)*(64.0*inversesqrt(dot(v+l,v+l)));
float NoH=clamp(dot(n,h),0.0,64.0);
float LoH=clamp(dot(l,h)*(1.0/64.0),0.0,1.0);
vec3 specular=specular_lobe(perceptualRoughness,alpha,NoV,NoL,NoH,LoH,n,v,l,h,f0);
vec3 irradiance=lightColor*NoL;
return min((specular_lobe_scalar(alpha,NoH,LoH,n,h)*NoL)*(f0*lightColor),65504.0);
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
highp vec3 shading_view_for_lights;
void main(){
shading_normal=normalize(v_normal);
shading_view_for_lights=normalize((frame.cameraPosition.xyz-v_worldPosition));
shading_view=shading_view_for_lights;
MaterialInputs material=material_defaults();
evaluate_surface(material);
vec3 color=apply_ambient_occlusion(material,material_diffuse_color(material)*v_diffuseLight);
color=linear_from_shading_space(color);
color=add_light(color,shade_standard_ambient_specular(material,shading_normal,shading_view));
highp vec3 l=frame.lightDirection.xyz;
color=add_light(color,shade_standard_direct(material,shading_normal,shading_view_for_lights,l,frame.lightColor.rgb));
fragColor=blend_output(add_light(color,linear_from_shading_space(material.emissive)),material.alpha);
}
