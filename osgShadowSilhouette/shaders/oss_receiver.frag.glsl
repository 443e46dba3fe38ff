#version 400 compatibility
// osgShadowSilhouette: receiver shading, fragment stage.
//
// Per-pixel Blinn-Phong with OpenGL's fixed-function terms (each light's ambient, diffuse
// and specular with attenuation and spot cone, osg::Material, the light model's ambient,
// the texture on unit 0). A light's shadow darkens only its own diffuse and specular.
// With OSS_DEBUG_MASK the pass writes the shadow mask of light oss_maskLight instead:
// 1 where that light reaches the surface, 0 where it is blocked or the surface's geometric
// normal faces away from it.

#pragma import_defines(OSS_BASE_TEXTURE, OSS_DEBUG_MASK)
#define OSS_MAX_SCENE_LIGHTS 8

in vec4 oss_eyePosition;
in vec3 oss_eyeNormal;
in vec4 oss_texCoord0;
in vec4 oss_color;

uniform int oss_numLights;
uniform int oss_lightIndex[OSS_MAX_SCENE_LIGHTS];
uniform int oss_maskLight;
uniform sampler2D oss_baseTexture;

float oss_shadowTerm(int light, vec4 eyePosition);

// Unit vector from the surface to light n, and the light's attenuation times spot factor.
vec3 oss_toLight(int n, out float falloff)
{
    vec4 lp = gl_LightSource[n].position;
    falloff = 1.0;
    if (lp.w == 0.0)
        return normalize(lp.xyz);
    vec3 d = lp.xyz / lp.w - oss_eyePosition.xyz;
    float dist = length(d);
    vec3 L = d / dist;
    falloff = 1.0 / (gl_LightSource[n].constantAttenuation + gl_LightSource[n].linearAttenuation * dist +
                     gl_LightSource[n].quadraticAttenuation * dist * dist);
    if (gl_LightSource[n].spotCutoff <= 90.0)
    {
        float c = dot(-L, normalize(gl_LightSource[n].spotDirection));
        falloff *= c < gl_LightSource[n].spotCosCutoff ? 0.0 : pow(max(c, 0.0), gl_LightSource[n].spotExponent);
    }
    return L;
}

#ifdef OSS_DEBUG_MASK
void main()
{
    vec3 p = oss_eyePosition.xyz;
    vec3 ng = normalize(cross(dFdx(p), dFdy(p)));
    if (dot(ng, -p) < 0.0)
        ng = -ng; // the geometric normal, facing the camera
    int n = oss_lightIndex[clamp(oss_maskLight, 0, OSS_MAX_SCENE_LIGHTS - 1)];
    float falloff;
    vec3 L = oss_toLight(n, falloff);
    bool facing = dot(ng, L) > 0.0 && falloff > 0.0 && oss_maskLight < oss_numLights;
    float lit = facing ? step(0.5, oss_shadowTerm(n, oss_eyePosition)) : 0.0;
    gl_FragColor = vec4(vec3(lit), 1.0);
}
#else
void main()
{
    vec3 N = normalize(oss_eyeNormal);
    vec3 V = normalize(-oss_eyePosition.xyz);
    vec4 ambient = gl_FrontMaterial.ambient * oss_color;
    vec4 diffuseColor = gl_FrontMaterial.diffuse * oss_color;
    vec4 color = gl_FrontMaterial.emission + gl_LightModel.ambient * ambient;
    vec4 specular = vec4(0.0);
    for (int k = 0; k < oss_numLights; ++k)
    {
        int n = oss_lightIndex[k];
        float falloff;
        vec3 L = oss_toLight(n, falloff);
        color += falloff * gl_LightSource[n].ambient * ambient;
        float nDotL = dot(N, L);
        if (nDotL <= 0.0 || falloff <= 0.0)
            continue;
        float shadow = oss_shadowTerm(n, oss_eyePosition);
        if (shadow <= 0.0)
            continue;
        color += shadow * falloff * nDotL * gl_LightSource[n].diffuse * diffuseColor;
        float nDotH = max(dot(N, normalize(L + V)), 0.0);
        float phong = gl_FrontMaterial.shininess > 0.0 ? pow(nDotH, gl_FrontMaterial.shininess) : 1.0;
        specular += shadow * falloff * phong * gl_LightSource[n].specular * gl_FrontMaterial.specular;
    }
    color.a = diffuseColor.a;
#ifdef OSS_BASE_TEXTURE
    color *= texture(oss_baseTexture, oss_texCoord0.st);
#endif
    gl_FragColor = vec4(color.rgb + specular.rgb, color.a);
}
#endif
