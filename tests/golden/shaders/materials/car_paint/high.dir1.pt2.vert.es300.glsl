#version 300 es
precision highp float;
precision highp int;
layout(location=0)in highp vec3 a_position;
layout(location=1)in highp vec3 a_normal;
out highp vec3 v_worldPosition;
out mediump vec3 v_normal;
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
highp mat4 model;
highp mat4 normalMatrix;
highp vec4 positionScale;
highp vec4 positionOffset;
highp vec4 uv0ScaleOffset;
highp vec4 uv1ScaleOffset;
}
object;
void main(){
highp vec3 position=a_position*object.positionScale.xyz+object.positionOffset.xyz;
highp vec4 worldPosition=object.model*vec4(position,1.0);
v_worldPosition=worldPosition.xyz;
v_normal=normalize(mat3(object.normalMatrix)*a_normal);
gl_Position=frame.viewProjection*worldPosition;
}
