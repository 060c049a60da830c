#version 300 es
precision mediump float;
precision highp int;
in mediump vec3 v_toEye;
in mediump vec3 v_normal;
in highp vec2 v_uv0;
in mediump vec4 v_tangent;
in mediump vec3 v_diffuseLight;
in mediump vec3 v_directDiffuse;
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
mediump float tiling;
mediump float roughness;
mediump float facet_pad8;
mediump float facet_pad12;
mediump float facet_perceptualRoughness;
mediump float facet_alpha;
mediump float facet_environmentLod;
mediump float facet_ggxAlphaScaled;
mediump float facet_ziomaRoughnessFactor;
}
params;
uniform mediump sampler2D facet_material_albedo;
uniform mediump sampler2D facet_material_relief;
uniform mediump sampler2D facet_specularLut;
uniform mediump samplerCube facet_environment;
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
float t0=2.0*params.tiling;
vec2 t1=vec2(t0,params.tiling);
highp vec2 m_uv=v_uv0*t1;
vec4 t2=texture(facet_material_albedo,m_uv);
vec3 t3=t2.xyz;
material.baseColor=t3;
material.roughness=params.roughness;
vec3 t4=texture(facet_material_relief,m_uv).xyz*(255.0/127.0)-(128.0/127.0);
material.normal=t4;
highp vec2 t5=m_uv*4.0;
highp vec2 m_tile=fract(t5);
highp float t6=m_tile.x;
highp float t7=1.0-t6;
highp float t8=min(t6,t7);
highp float t9=m_tile.y;
highp float t10=1.0-t9;
highp float t11=min(t9,t10);
highp float m_edge=min(t8,t11);
highp float t12=smoothstep(0.0,0.35,m_edge);
highp float t13=mix(0.4,1.0,t12);
material.ambientOcclusion=t13;
}
vec3 tangent_to_world(vec3 tangentNormal){
vec3 n=v_normal;
vec3 t=v_tangent.xyz;
if(dot(t,t)==0.0)return normalize(n);
vec3 b=v_tangent.w*cross(n,t);
return normalize(tangentNormal.x*t+tangentNormal.y*b+tangentNormal.z*n);
}
vec3 env_brdf_karis(vec3 f0,float NoV,float perceptualRoughness){
vec4 k=perceptualRoughness*vec4(-1.0,-0.0275,-0.572,0.022)+vec4(1.0,0.0425,1.04,-0.04);
float s=min(k.x*k.x,exp2(-9.28*NoV))*k.x+k.y;
vec2 ab=vec2(-1.04,1.04)*s+k.zw;
return f0*ab.x+ab.y;
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
return params.facet_perceptualRoughness;
}
vec3 shading_specular_albedo=vec3(0.0);
vec3 multi_bounce_ao(float visibility,vec3 albedo){
vec3 a=2.0404*albedo-0.3324;
vec3 b= -4.7951*albedo+0.6417;
vec3 c=2.7552*albedo+0.6903;
return max(vec3(visibility),((visibility*a+b)*visibility+c)*visibility);
}
vec3 apply_ambient_occlusion(MaterialInputs material,vec3 ambient){
return ambient*multi_bounce_ao(clamp(material.ambientOcclusion,0.0,1.0),material_diffuse_color(material));
}
vec3 apply_specular_occlusion(MaterialInputs material,vec3 specular,float NoV,float perceptualRoughness){
float visibility=clamp(material.ambientOcclusion,0.0,1.0);
return specular*visibility;
}
vec3 shade_standard_ambient_specular(MaterialInputs material,vec3 n,vec3 v){
vec3 f0=material_f0(material);
float perceptualRoughness=material_perceptual_roughness(material);
float NoV=max(dot(n,v),MIN_N_DOT_V);
vec3 r=reflect(-v,n);
vec3 albedo=env_brdf_karis(f0,NoV,perceptualRoughness);
vec3 specular=textureLod(facet_environment,r,params.facet_environmentLod).rgb;
shading_specular_albedo=albedo;
return apply_specular_occlusion(material,specular*albedo,NoV,perceptualRoughness);
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
vec3 directLight=v_directDiffuse;
vec3 color=apply_ambient_occlusion(material,material_diffuse_color(material)*v_diffuseLight);
vec3 directDiffuse=material_diffuse_color(material)*directLight;
color+=directDiffuse;
color=linear_from_shading_space(color);
color=add_light(color,shade_standard_ambient_specular(material,shading_normal,shading_view));
fragColor=blend_output(add_light(color,linear_from_shading_space(material.emissive)),material.alpha);
}
