#version 300 es
precision highp float;
precision highp int;
in highp vec3 v_worldPosition;
in highp vec3 v_normal;
in highp vec2 v_uv0;
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
highp float tiling;
highp float roughness;
highp float facet_pad20;
highp float facet_pad24;
highp float facet_pad28;
highp vec3 facet_diffuseColor;
highp float facet_perceptualRoughness;
highp vec3 facet_f0;
highp float facet_alpha;
highp float facet_environmentLod;
highp float facet_ggxAlphaScaled;
highp float facet_ziomaRoughnessFactor;
}
params;
uniform highp sampler2D facet_material_ripples;
uniform highp samplerCube facet_environment;
uniform highp sampler2D facet_dfgLut;
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
float diffuse_lambert(){
return 0.31830988618;
}
float ggx_d_scaled(float alpha,float NoH,vec3 n,vec3 h){
vec4 t=64.0*vec4(cross(n,h),alpha*NoH);
return dot(t,t);
}
float distribution_ggx(float alpha,float NoH,vec3 n,vec3 h){
float k=4096.0*alpha/ggx_d_scaled(alpha,NoH,n,h);
return(k*k*0.31830988618);
}
float visibility_smith_ggx_correlated(float alpha,float NoV,float NoL){
float a2=alpha*alpha;
float lambdaV=NoL*sqrt(NoV*NoV*(1.0-a2)+a2);
float lambdaL=NoV*sqrt(NoL*NoL*(1.0-a2)+a2);
return(0.5/(lambdaV+lambdaL));
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
return(D*V)*fresnel_schlick(f0,LoH);
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
vec3 prefiltered_radiance(vec3 direction,float r){
return textureLod(facet_environment,direction,r*(float(5-1)*(2.0-r))).rgb;
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
vec3 specular=prefiltered_radiance(r,perceptualRoughness);
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
shading_normal=tangent_to_world(material.normal);
material.roughness=specular_aa_roughness(material_perceptual_roughness(material),shading_normal);
vec3 color=shade_standard_ambient(material,sh_irradiance_over_pi(shading_normal));
color=linear_from_shading_space(color);
color=add_light(color,shade_standard_ambient_specular(material,shading_normal,shading_view));
highp vec3 l=frame.lightDirection.xyz;
color=add_light(color,shade_standard_direct(material,shading_normal,shading_view_for_lights,l,frame.lightColor.rgb));
color=add_light(color,shade_punctual(material,frame.punctualLights[0]));
color=add_light(color,shade_punctual(material,frame.punctualLights[1]));
fragColor=blend_output(add_light(color,linear_from_shading_space(material.emissive)),material.alpha);
}
