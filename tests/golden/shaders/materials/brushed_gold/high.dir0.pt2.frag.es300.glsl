#version 300 es
precision mediump float;
precision highp int;
in highp vec3 v_worldPosition;
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
mediump vec3 tint;
mediump float roughness;
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
material.baseColor=params.tint;
material.metallic=1.0;
material.roughness=params.roughness;
}
float diffuse_lambert(){
return 0.31830988618;
}
float ggx_d_scaled(float alpha,float NoH,vec3 n,vec3 h){
vec4 t=64.0*vec4(cross(n,h),alpha*NoH);
return dot(t,t);
}
float distribution_ggx(float alpha,float NoH,vec3 n,vec3 h){
float k=4096.0*alpha/ggx_d_scaled(alpha,NoH,n,h);
return min(k*k*0.31830988618,65504.0);
}
float visibility_smith_ggx_correlated(float alpha,float NoV,float NoL){
float a2=alpha*alpha;
float lambdaV=NoL*sqrt(NoV*NoV*(1.0-a2)+a2);
float lambdaL=NoV*sqrt(NoL*NoL*(1.0-a2)+a2);
return min(0.5/(lambdaV+lambdaL),65504.0);
}
vec3 fresnel_schlick(vec3 f0,float LoH){
float f=1.0-LoH;
float f2=f*f;
float f5=f2*f2*f;
return f0+(vec3(1.0)-f0)*f5;
}
vec3 specular_lobe(float perceptualRoughness,float alpha,float NoV,float NoL,float NoH,float LoH,vec3 n,vec3 v,vec3 l,vec3 h,vec3 f0){
float D=distribution_ggx(alpha,NoH,n,h);
float V=visibility_smith_ggx_correlated(alpha,NoV,NoL);
return min(D*V,65504.0)*fresnel_schlick(f0,LoH);
}
vec3 sh_irradiance_over_pi(vec3 n){
vec3 c0=frame.sh[0].rgb;
vec3 c1=frame.sh[1].rgb;
vec3 c2=frame.sh[2].rgb;
vec3 c3=frame.sh[3].rgb;
vec3 e=c0+c1*n.y+c2*n.z+c3*n.x;
vec3 c4=frame.sh[4].rgb;
vec3 c5=frame.sh[5].rgb;
vec3 c6=frame.sh[6].rgb;
vec3 c7=frame.sh[7].rgb;
vec3 c8=frame.sh[8].rgb;
e+=c4*(n.x*n.y)+c5*(n.y*n.z)+c6*(3.0*n.z*n.z-1.0)+c7*(n.x*n.z)+c8*(n.x*n.x-n.y*n.y);
return max(e,vec3(0.0));
}
vec2 dfg_terms(float NoV,float perceptualRoughness){
return textureLod(facet_dfgLut,vec2(NoV,perceptualRoughness),0.0).rg;
}
vec3 split_sum_albedo(vec2 dfg,vec3 f0){
return mix(dfg.xxx,dfg.yyy,f0);
}
vec3 energy_compensation(vec2 dfg,vec3 f0){
return 1.0+f0*(1.0/dfg.y-1.0);
}
vec3 material_diffuse_color(MaterialInputs material){
return(1.0-clamp(material.metallic,0.0,1.0))*clamp(material.baseColor,0.0,1.0);
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
vec3 shading_energy_compensation=vec3(1.0);
vec3 half_vector(highp vec3 v,highp vec3 l){
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
vec3 h=half_vector(viewHighp,lightHighp);
float NoH=clamp(dot(n,h),0.0,1.0);
float LoH=clamp(dot(l,h),0.0,1.0);
vec3 specular=specular_lobe(perceptualRoughness,alpha,NoV,NoL,NoH,LoH,n,v,l,h,f0);
specular*=shading_energy_compensation;
vec3 irradiance=lightColor*NoL;
vec3 diffuseColor=material_diffuse_color(material);
return min((diffuseColor*diffuse_lambert()+specular)*irradiance,65504.0);
}
vec3 apply_ambient_occlusion(MaterialInputs material,vec3 ambient){
return ambient;
}
vec3 shade_standard_ambient(MaterialInputs material,vec3 irradianceOverPi){
return apply_ambient_occlusion(material,material_diffuse_color(material)*irradianceOverPi);
}
vec3 shade_standard_ambient_specular(MaterialInputs material,vec3 n,vec3 v){
vec3 f0=material_f0(material);
float perceptualRoughness=material_perceptual_roughness(material);
float NoV=max(dot(n,v),MIN_N_DOT_V);
vec3 r=reflect(-v,n);
vec2 dfg=dfg_terms(NoV,perceptualRoughness);
vec3 albedo=split_sum_albedo(dfg,f0);
shading_energy_compensation=energy_compensation(dfg,f0);
vec3 specular=textureLod(facet_environment,r,params.facet_environmentLod).rgb;
albedo*=shading_energy_compensation;
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
vec3 color=shade_standard_ambient(material,sh_irradiance_over_pi(shading_normal));
color=linear_from_shading_space(color);
color=add_light(color,shade_standard_ambient_specular(material,shading_normal,shading_view));
color=add_light(color,shade_punctual(material,frame.punctualLights[0]));
color=add_light(color,shade_punctual(material,frame.punctualLights[1]));
fragColor=blend_output(add_light(color,linear_from_shading_space(material.emissive)),material.alpha);
}
