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
mediump vec3 baseColor;
mediump float roughness;
mediump float reflectance;
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
uniform mediump samplerCube facet_environment;
uniform mediump sampler2D facet_dfgLut;
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
material.baseColor=params.baseColor;
material.metallic=0.0;
material.roughness=params.roughness;
material.reflectance=params.reflectance;
}
float ggx_d_scaled(float alpha,float NoH,vec3 n,vec3 h){
vec4 t=vec4(cross(n,h),alpha*NoH);
return dot(t,t);
}
const float ZIOMA_LOH2_MIN=0.15;
float specular_zioma_kkx(float a,float d,float x){
float k=a/(d*x);
return min(k*k*x,65504.0);
}
float specular_lobe_scalar(float alpha,float NoH,float LoH,vec3 n,vec3 h){
float x=max(LoH*LoH,ZIOMA_LOH2_MIN)*params.facet_ziomaRoughnessFactor;
return specular_zioma_kkx(params.facet_ggxAlphaScaled,ggx_d_scaled(alpha,NoH,n,h),x);
}
vec3 specular_lobe(float perceptualRoughness,float alpha,float NoV,float NoL,float NoH,float LoH,vec3 n,vec3 v,vec3 l,vec3 h,vec3 f0){
return specular_lobe_scalar(alpha,NoH,LoH,n,h)*f0;
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
return params.facet_perceptualRoughness;
}
float material_alpha(MaterialInputs material){
return params.facet_alpha;
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
vec3 specular=textureLod(facet_environment,r,params.facet_environmentLod).rgb;
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
vec3 punctual_light_illuminance(PunctualLightData light,highp vec3 worldPosition,out highp vec3 l){
highp vec3 toLight=light.positionFalloff.xyz-worldPosition;
highp float distanceSquared=dot(toLight,toLight);
l=toLight*inversesqrt(max(distanceSquared,1e-8));
highp float ratio=distanceSquared*light.positionFalloff.w;
float window=clamp(1.0-ratio*ratio,0.0,1.0);
float attenuation=window*window/max(distanceSquared,1e-4);
float cone=clamp(dot(-l,light.direction.xyz)*light.spotScaleOffset.x+light.spotScaleOffset.y,0.0,1.0);
return min(light.colorIntensity.rgb*(attenuation*cone*cone),65504.0);
}
vec3 shade_punctual(MaterialInputs material,PunctualLightData light){
highp vec3 l;
vec3 illuminance=punctual_light_illuminance(light,v_worldPosition,l);
return shade_standard_direct(material,shading_normal,shading_view_for_lights,l,illuminance);
}
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
color=add_light(color,shade_punctual(material,frame.punctualLights[0]));
color=add_light(color,shade_punctual(material,frame.punctualLights[1]));
fragColor=blend_output(add_light(color,linear_from_shading_space(material.emissive)),material.alpha);
}
