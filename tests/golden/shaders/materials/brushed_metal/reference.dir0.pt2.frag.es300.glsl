#version 300 es
precision highp float;
precision highp int;
in highp vec3 v_worldPosition;
in highp vec3 v_normal;
in highp vec4 v_tangent;
layout(location=0)out highp vec4 fragColor;
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
highp vec3 tint;
highp float roughness;
highp float anisotropy;
highp float facet_pad20;
highp float facet_pad24;
highp float facet_pad28;
highp float facet_perceptualRoughness;
highp vec3 facet_f0;
highp float facet_alpha;
highp float facet_environmentLod;
highp float facet_ggxAlphaScaled;
highp float facet_ziomaRoughnessFactor;
highp float facet_anisotropy;
highp float facet_anisotropicBend;
highp vec2 facet_anisotropicAlpha;
}
params;
uniform highp samplerCube facet_environment;
uniform highp sampler2D facet_dfgLut;
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
float anisotropy;
vec3 anisotropyDirection;
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
m.anisotropy=0.0;
m.anisotropyDirection=vec3(1.0,0.0,0.0);
return m;
}
vec3 shading_normal;
vec3 shading_view;
void evaluate_surface(inout MaterialInputs material){
material.baseColor=params.tint;
material.metallic=1.0;
material.roughness=params.roughness;
material.anisotropy=params.anisotropy;
}
float diffuse_lambert(){
return 0.31830988618;
}
vec3 fresnel_schlick(vec3 f0,float LoH){
float f=1.0-LoH;
float f2=f*f;
float f5=f2*f2*f;
return f0+(vec3(1.0)-f0)*f5;
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
vec3 shading_anisotropic_t;
float anisotropy_strength(MaterialInputs material){
return params.facet_anisotropy;
}
vec2 anisotropic_alpha(MaterialInputs material,float alpha){
return params.facet_anisotropicAlpha;
}
void anisotropy_frame(MaterialInputs material,vec3 n){
vec3 t=v_tangent.xyz;
t-=n*dot(n,t);
vec3 fallback=abs(n.z)<0.5?vec3(-n.y,n.x,0.0):vec3(0.0,-n.z,n.y);
t=normalize(dot(t,t)>1.0e-3?t:fallback);
shading_anisotropic_t=t;
}
vec3 anisotropic_reflection(MaterialInputs material,vec3 n,vec3 v,float NoV,float perceptualRoughness){
float k=anisotropy_strength(material);
vec3 e=k>=0.0?shading_anisotropic_t:cross(n,shading_anisotropic_t);
float EoV=dot(e,v);
float bend=params.facet_anisotropicBend;
float c1=1.0-bend*(1.0-NoV);
float c2=bend*EoV;
float MoV=c1*NoV+c2*EoV;
return(512.0*MoV)*(c1*n+c2*e)-(256.0*(c1*c1+c2*c2))*v;
}
const float ANISOTROPY_V_SCALE=128.0;
vec3 shading_anisotropic_b;
vec2 shading_anisotropy_inverse_alpha;
vec2 shading_anisotropy_scaled_alpha;
float shading_anisotropy_d_scale;
float shading_anisotropy_view_length;
void anisotropy_setup(MaterialInputs material,float alpha,vec3 n,float NoV,vec3 v){
shading_anisotropic_b=cross(n,shading_anisotropic_t);
vec2 a=anisotropic_alpha(material,alpha);
shading_anisotropy_inverse_alpha=1.0/a;
shading_anisotropy_scaled_alpha=ANISOTROPY_V_SCALE*a;
shading_anisotropy_d_scale=0.31830988618*(shading_anisotropy_inverse_alpha.x*shading_anisotropy_inverse_alpha.y);
vec2 tb=vec2(dot(shading_anisotropic_t,v),dot(shading_anisotropic_b,v));
shading_anisotropy_view_length=length(vec3(shading_anisotropy_scaled_alpha*tb,ANISOTROPY_V_SCALE*NoV));
}
float anisotropic_ggx_smith(float NoV,float NoL,float NoH,vec3 l,vec3 h){
vec2 x=vec2(dot(shading_anisotropic_t,h),dot(shading_anisotropic_b,h))*shading_anisotropy_inverse_alpha;
float q=1.0/(dot(x,x)+NoH*NoH);
float D=(shading_anisotropy_d_scale*q)*q;
vec2 tb=vec2(dot(shading_anisotropic_t,l),dot(shading_anisotropic_b,l));
float lightLength=length(vec3(shading_anisotropy_scaled_alpha*tb,ANISOTROPY_V_SCALE*NoL));
float V=((0.5*ANISOTROPY_V_SCALE)/(NoL*shading_anisotropy_view_length+NoV*lightLength));
return(D*V);
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
vec3 specular=anisotropic_ggx_smith(NoV,NoL,NoH,l,h)*fresnel_schlick(f0,LoH);
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
vec3 r=anisotropic_reflection(material,n,v,NoV,perceptualRoughness);
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
return(light.colorIntensity.rgb*(attenuation*cone*cone));
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
anisotropy_frame(material,shading_normal);
anisotropy_setup(material,material_alpha(material),shading_normal,max(dot(shading_normal,shading_view),MIN_N_DOT_V),shading_view);
vec3 color=shade_standard_ambient(material,sh_irradiance_over_pi(shading_normal));
color=linear_from_shading_space(color);
color=add_light(color,shade_standard_ambient_specular(material,shading_normal,shading_view));
color=add_light(color,shade_punctual(material,frame.punctualLights[0]));
color=add_light(color,shade_punctual(material,frame.punctualLights[1]));
fragColor=blend_output(add_light(color,linear_from_shading_space(material.emissive)),material.alpha);
}
