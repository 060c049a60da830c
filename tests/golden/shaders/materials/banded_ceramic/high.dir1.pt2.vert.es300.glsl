#version 300 es
precision highp float;
precision highp int;
layout(location=0)in highp vec3 a_position;
layout(location=1)in highp vec3 a_normal;
layout(location=6)in highp vec4 a_instanceRow0;
layout(location=7)in highp vec4 a_instanceRow1;
layout(location=8)in highp vec4 a_instanceRow2;
out highp vec3 v_worldPosition;
out mediump vec3 v_normal;
out mediump vec3 v_diffuseLight;
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
layout(std140)uniform ObjectUniforms{
highp vec4 positionScale;
highp vec4 positionOffset;
highp vec4 uv0ScaleOffset;
highp vec4 uv1ScaleOffset;
}
object;
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
vec3 punctual_diffuse(PunctualLightData light,highp vec3 worldPosition,vec3 n){
highp vec3 l;
vec3 illuminance=punctual_light_illuminance(light,worldPosition,l);
return illuminance*(clamp(dot(n,l),0.0,1.0)*0.31830988618);
}
void main(){
highp vec3 position=a_position*object.positionScale.xyz+object.positionOffset.xyz;
highp vec4 objectPosition=vec4(position,1.0);
highp vec4 worldPosition=vec4(dot(a_instanceRow0,objectPosition),dot(a_instanceRow1,objectPosition),dot(a_instanceRow2,objectPosition),1.0);
v_worldPosition=worldPosition.xyz;
highp vec3 row0=a_instanceRow0.xyz,row1=a_instanceRow1.xyz,row2=a_instanceRow2.xyz;
highp vec3 cofactor0=cross(row1,row2);
highp vec3 objectNormal=dot(row0,cofactor0)<0.0?-a_normal:a_normal;
v_normal=normalize(objectNormal*mat3(cofactor0,cross(row2,row0),cross(row0,row1)));
vec3 n=v_normal;
vec3 irradiance=sh_irradiance_over_pi(n);
irradiance+=frame.lightColor.rgb*(clamp(dot(n,frame.lightDirection.xyz),0.0,1.0)*0.31830988618);
irradiance+=punctual_diffuse(frame.punctualLights[0],worldPosition.xyz,n);
irradiance+=punctual_diffuse(frame.punctualLights[1],worldPosition.xyz,n);
v_diffuseLight=irradiance;
gl_Position=frame.viewProjection*worldPosition;
}
