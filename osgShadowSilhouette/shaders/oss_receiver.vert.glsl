#version 400 compatibility
// osgShadowSilhouette: receiver shading, vertex stage.
//
// Lights each vertex exactly as OpenGL's fixed function does (per vertex: each light's
// ambient, diffuse and specular with attenuation and spot cone, osg::Material, the light
// model's ambient), but keeps the diffuse + specular of every shadowed light apart, so the
// fragment stage can scale each by its own shadow term. The scene therefore looks as it
// does without the technique wherever no shadow falls.

#pragma import_defines(OSS_MAX_SHADOW_LIGHTS)
#ifndef OSS_MAX_SHADOW_LIGHTS
#define OSS_MAX_SHADOW_LIGHTS 1
#endif
#define OSS_MAX_SCENE_LIGHTS 8

uniform int oss_numLights;
uniform int oss_lightIndex[OSS_MAX_SCENE_LIGHTS];
uniform int oss_shadowSlot[OSS_MAX_SCENE_LIGHTS];

out vec4 oss_eyePosition;
out vec4 oss_texCoord0;
out vec4 oss_unshadowedColor;                       // emission, ambients, unshadowed lights
out vec3 oss_shadowedColor[OSS_MAX_SHADOW_LIGHTS];  // diffuse + specular of shadow slot s

// Diffuse + specular of GL light n at eye-space point p with unit normal N; ambient returned apart.
vec3 oss_lightVertex(int n, vec3 p, vec3 N, vec4 ambientColor, vec4 diffuseColor, out vec3 ambient)
{
    vec4 lp = gl_LightSource[n].position;
    vec3 L = lp.w == 0.0 ? normalize(lp.xyz) : lp.xyz / lp.w - p;
    float falloff = 1.0;
    if (lp.w != 0.0)
    {
        float dist = length(L);
        L /= dist;
        falloff = 1.0 / (gl_LightSource[n].constantAttenuation + gl_LightSource[n].linearAttenuation * dist +
                         gl_LightSource[n].quadraticAttenuation * dist * dist);
        if (gl_LightSource[n].spotCutoff <= 90.0)
        {
            float c = dot(-L, normalize(gl_LightSource[n].spotDirection));
            falloff *= c < gl_LightSource[n].spotCosCutoff ? 0.0 : pow(max(c, 0.0), gl_LightSource[n].spotExponent);
        }
    }
    ambient = falloff * (gl_LightSource[n].ambient * ambientColor).rgb;
    float nDotL = dot(N, L);
    if (nDotL <= 0.0)
        return vec3(0.0);
    vec3 H = normalize(L + vec3(0.0, 0.0, 1.0)); // GL_LIGHT_MODEL_LOCAL_VIEWER off
    float nDotH = max(dot(N, H), 0.0);
    float phong = gl_FrontMaterial.shininess > 0.0 ? pow(nDotH, gl_FrontMaterial.shininess) : 1.0;
    return falloff * (nDotL * (gl_LightSource[n].diffuse * diffuseColor).rgb +
                      phong * (gl_LightSource[n].specular * gl_FrontMaterial.specular).rgb);
}

void main()
{
    oss_eyePosition = gl_ModelViewMatrix * gl_Vertex;
    oss_texCoord0 = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_Position = ftransform();

    // A zero or non-finite normal (models carry them) lights nothing directly, as in the
    // fixed function, instead of spreading NaN through the shading.
    vec3 n = gl_NormalMatrix * gl_Normal;
    float nLength = length(n);
    vec3 N = nLength > 0.0 && nLength < 1e30 ? n / nLength : vec3(0.0);
    vec4 ambientColor = gl_FrontMaterial.ambient * gl_Color;
    vec4 diffuseColor = gl_FrontMaterial.diffuse * gl_Color;
    vec3 color = gl_FrontMaterial.emission.rgb + (gl_LightModel.ambient * ambientColor).rgb;
    for (int s = 0; s < OSS_MAX_SHADOW_LIGHTS; ++s)
        oss_shadowedColor[s] = vec3(0.0);
    for (int k = 0; k < oss_numLights; ++k)
    {
        vec3 ambient;
        vec3 direct = oss_lightVertex(oss_lightIndex[k], oss_eyePosition.xyz, N, ambientColor, diffuseColor, ambient);
        color += ambient;
        int slot = oss_shadowSlot[k];
        if (slot >= 0 && slot < OSS_MAX_SHADOW_LIGHTS)
            oss_shadowedColor[slot] = direct;
        else
            color += direct;
    }
    oss_unshadowedColor = vec4(color, diffuseColor.a);
}
