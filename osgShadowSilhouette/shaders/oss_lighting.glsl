#version 400 compatibility
// osgShadowSilhouette: OpenGL's fixed-function lighting equation, linked into the receivers'
// vertex stage (lighting per vertex, as the fixed function does) and, with
// OSS_PER_PIXEL_LIGHTING (the property PerPixelLighting), into their fragment stage
// (oss_fragment_lighting.frag.glsl): one source for both.
//
// Each light's ambient, diffuse and specular with attenuation and spot cone, osg::Material
// (gl_FrontMaterial), the light model's ambient; the diffuse + specular of every shadowed
// light kept apart, so the fragment stage can scale each by its own shadow term.

#pragma import_defines(OSS_MAX_SHADOW_LIGHTS)

uniform int oss_numLights;
uniform int oss_lightIndex[OSS_MAX_SCENE_LIGHTS];
uniform int oss_shadowSlot[OSS_MAX_SCENE_LIGHTS];

// Diffuse + specular of GL light n at eye-space point p with unit normal N; ambient returned apart.
vec3 oss_lightPoint(int n, vec3 p, vec3 N, vec4 ambientColor, vec4 diffuseColor, out vec3 ambient)
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

// The colour of eye-space point p with normal n (any length; a zero or non-finite normal
// lights nothing directly, as in the fixed function, instead of spreading NaN) and primary
// colour `color`: emission, ambients and the unshadowed lights, with the material's diffuse
// alpha; shadowed[s]: the diffuse + specular of shadow slot s.
vec4 oss_lighting(vec3 p, vec3 n, vec4 color, out vec3 shadowed[OSS_MAX_SHADOW_LIGHTS])
{
    float nLength = length(n);
    vec3 N = nLength > 0.0 && nLength < 1e30 ? n / nLength : vec3(0.0);
    vec4 ambientColor = gl_FrontMaterial.ambient * color;
    vec4 diffuseColor = gl_FrontMaterial.diffuse * color;
    vec3 sum = gl_FrontMaterial.emission.rgb + (gl_LightModel.ambient * ambientColor).rgb;
    for (int s = 0; s < OSS_MAX_SHADOW_LIGHTS; ++s)
        shadowed[s] = vec3(0.0);
    for (int k = 0; k < oss_numLights; ++k)
    {
        vec3 ambient;
        vec3 direct = oss_lightPoint(oss_lightIndex[k], p, N, ambientColor, diffuseColor, ambient);
        sum += ambient;
        int slot = oss_shadowSlot[k];
        if (slot >= 0 && slot < OSS_MAX_SHADOW_LIGHTS)
            shadowed[slot] = direct;
        else
            sum += direct;
    }
    return vec4(sum, diffuseColor.a);
}
