#include "render/shaders.h"

#include <cassert>
#include <string>

#include <osg/Shader>

namespace thespis::core::render::shaders {

namespace {

// Linear radiance → display value: exposure, clamp, sRGB encoding. The power segment of the sRGB
// curve, 1.055·c^(1/2.4) − 0.055 on [0.0031308, 1], is a least-squares fit in c^(1/2), c^(1/4),
// c^(1/8) and c (largest error 0.011/255): square roots are single instructions where llvmpipe's
// pow() took a third of the frame.
constexpr const char* kDisplayFunctions = R"(
uniform float exposure;
vec3 encodeSrgb(vec3 linear)
{
    vec3 c = clamp(linear, 0.0, 1.0);
    vec3 s1 = sqrt(c);
    vec3 s2 = sqrt(s1);
    vec3 s3 = sqrt(s2);
    vec3 curve = 0.642385812 * s1 + 0.712090535 * s2 - 0.336862394 * s3 - 0.017570844 * c;
    return mix(12.92 * c, curve, step(vec3(0.0031308), c));
}
vec3 toDisplay(vec3 radiance) { return encodeSrgb(exposure * radiance); }
)";

constexpr const char* kAlbedoFunction = R"(
uniform vec4 baseColor;
uniform sampler2D baseColorTexture;
uniform float textureWeight;
varying vec2 v_texcoord;
vec3 albedo()
{
    vec3 texel = texture2D(baseColorTexture, v_texcoord).rgb;
    return baseColor.rgb * mix(vec3(1.0), texel, textureWeight);
}
)";

// The selection highlight of the segment tag editor, applied last in every character shading
// mode so that it reads the same whatever the light and material: 35 % of the way to orange, plus
// a bright orange rim where the surface turns away from the eye (an outline on any colour). Display values in and out; with
// selectionHighlight = 0 the colour is returned unchanged.
constexpr const char* kSelectionFunction = R"(
uniform float selectionHighlight;
uniform mat4 osg_ViewMatrixInverse;
vec3 selectionTint(vec3 display, vec3 position, vec3 normal)
{
    if (selectionHighlight < 0.5)
        return display;
    const vec3 selection = vec3(1.0, 0.55, 0.1);
    vec3 toEye = normalize(osg_ViewMatrixInverse[3].xyz - position);
    float rim = 1.0 - abs(dot(normalize(normal), toEye));
    return clamp(mix(display, selection, 0.35) + vec3(1.0, 0.7, 0.3) * (rim * rim), 0.0, 1.0);
}
)";

std::string transferName(int attribute) { return "a_transfer" + std::to_string(attribute); }

// PRT per vertex, as the paper evaluates it: the dot product is unrolled over the vec4 lanes.
std::string prtVertexSource(int order)
{
    const int coefficients = order * order;
    std::string source = "#version 120\n";
    source += "uniform vec3 shLight[" + std::to_string(coefficients) + "];\n";
    source += "attribute vec2 a_texcoord;\n";
    for (int a = 0; a < transferAttributeCount(order); ++a)
        source += "attribute vec4 " + transferName(a) + ";\n";
    source += "varying vec2 v_texcoord;\nvarying vec3 v_radiance;\nvarying vec3 v_position;\nvarying vec3 v_normal;\n";
    source += "void main()\n{\n    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n";
    source += "    v_texcoord = a_texcoord;\n    v_position = gl_Vertex.xyz;\n    v_normal = gl_Normal;\n";
    source += "    vec3 radiance = vec3(0.0);\n";
    static constexpr const char* lanes = "xyzw";
    for (int i = 0; i < coefficients; ++i)
        source += "    radiance += " + transferName(i / 4) + "." + lanes[i % 4] + " * shLight[" + std::to_string(i) + "];\n";
    source += "    v_radiance = radiance;\n}\n";
    return source;
}

constexpr const char* kPrtFragment = R"(
varying vec3 v_radiance;
varying vec3 v_position;
varying vec3 v_normal;
void main()
{
    vec3 display = toDisplay(albedo() * max(v_radiance, vec3(0.0)));
    gl_FragColor = vec4(selectionTint(display, v_position, v_normal), 1.0);
}
)";

constexpr const char* kWorldVertex = R"(#version 120
attribute vec2 a_texcoord;
varying vec2 v_texcoord;
varying vec3 v_position;
varying vec3 v_normal;
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
    v_texcoord = a_texcoord;
    v_position = gl_Vertex.xyz;
    v_normal = gl_Normal;
}
)";

// Normalised Blinn-Phong: f = albedo/π + ks·(s+8)/(8π)·(n·h)^s, lit by the directional light and
// the ambient irradiance (which only the diffuse part receives).
constexpr const char* kPhongFragment = R"(
uniform vec3 lightDirection;
uniform vec3 lightColor;
uniform vec3 ambientIrradiance;
varying vec3 v_position;
varying vec3 v_normal;
const float pi = 3.14159265;
const float shininess = 32.0;
const float specularAlbedo = 0.04;
void main()
{
    vec3 n = normalize(v_normal);
    vec3 toEye = normalize(osg_ViewMatrixInverse[3].xyz - v_position);
    vec3 h = normalize(lightDirection + toEye);
    float cosine = max(dot(n, lightDirection), 0.0);
    float specular = cosine > 0.0
        ? specularAlbedo * (shininess + 8.0) / (8.0 * pi) * pow(max(dot(n, h), 0.0), shininess) : 0.0;
    vec3 radiance = albedo() / pi * (ambientIrradiance + lightColor * cosine) + lightColor * (specular * cosine);
    gl_FragColor = vec4(selectionTint(toDisplay(radiance), v_position, v_normal), 1.0);
}
)";

constexpr const char* kUnlitFragment = R"(
varying vec3 v_position;
varying vec3 v_normal;
void main()
{
    gl_FragColor = vec4(selectionTint(encodeSrgb(albedo()), v_position, v_normal), 1.0);
}
)";

constexpr const char* kGroundFragment = R"(
uniform vec3 groundColor;
varying vec3 v_position;
float gridLine(float coordinate)
{
    float distance = abs(fract(coordinate + 0.5) - 0.5) / max(fwidth(coordinate), 1e-6);
    return clamp(1.0 - distance, 0.0, 1.0);
}
void main()
{
    float line = max(gridLine(v_position.x), gridLine(v_position.z));
    gl_FragColor = vec4(toDisplay(groundColor * (1.0 - 0.3 * line)), 1.0);
}
)";

// Over video: the real ground shows through, darkened where the characters hide the sky from it.
// The shadow is worked out on the CPU into a small texture over the characters' footprint
// (ArCompositor): here a square of the ground, placed by shadowArea (centre x, z and half side),
// only looks it up.
constexpr const char* kShadowCatcherVertex = R"(#version 120
uniform vec3 shadowArea;
varying vec2 v_uv;
void main()
{
    vec2 ground = shadowArea.xy + gl_Vertex.xz * shadowArea.z;
    gl_Position = gl_ModelViewProjectionMatrix * vec4(ground.x, 0.0, ground.y, 1.0);
    v_uv = gl_Vertex.xz * 0.5 + 0.5;
}
)";
constexpr const char* kShadowCatcherFragment = R"(#version 120
uniform sampler2D shadowTexture;
uniform float shadowStrength;
varying vec2 v_uv;
void main() { gl_FragColor = vec4(0.0, 0.0, 0.0, shadowStrength * texture2D(shadowTexture, v_uv).r); }
)";

// Phantom occluders write depth only (their colour is masked off); the program keeps GL's
// fixed-function path out of a scene that is all shaders.
constexpr const char* kDepthOnlyVertex = R"(#version 120
void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }
)";
constexpr const char* kDepthOnlyFragment = R"(#version 120
void main() { gl_FragColor = vec4(0.0); }
)";

// The quad covers the screen at the far plane (z = w), so it shows only where nothing was drawn.
constexpr const char* kBackgroundVertex = R"(#version 120
varying vec2 v_ndc;
void main()
{
    v_ndc = gl_Vertex.xy;
    gl_Position = vec4(gl_Vertex.xy, 1.0, 1.0);
}
)";

// Lat-long lookup as in lighting/probe.h: top row +y, centre column −z, right turns to +x.
constexpr const char* kBackgroundFragment = R"(
uniform sampler2D probeTexture;
uniform mat4 osg_ViewMatrixInverse;
varying vec2 v_ndc;
const float pi = 3.14159265;
void main()
{
    vec4 eyePoint = gl_ProjectionMatrixInverse * vec4(v_ndc, 1.0, 1.0);
    vec3 d = normalize(mat3(osg_ViewMatrixInverse) * (eyePoint.xyz / eyePoint.w));
    vec2 uv = vec2(0.5 + atan(d.x, -d.z) / (2.0 * pi), acos(clamp(d.y, -1.0, 1.0)) / pi);
    gl_FragColor = vec4(toDisplay(texture2D(probeTexture, uv).rgb), 1.0);
}
)";

osg::ref_ptr<osg::Program> makeProgram(const std::string& name, const std::string& vertex, const std::string& fragment)
{
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName(name);
    program->addShader(new osg::Shader(osg::Shader::VERTEX, vertex));
    program->addShader(new osg::Shader(osg::Shader::FRAGMENT, fragment));
    return program;
}

// Character fragments (withAlbedo) also get the selection tint.
std::string fragmentSource(const char* body, bool withAlbedo)
{
    return std::string("#version 120\n") + kDisplayFunctions + (withAlbedo ? kAlbedoFunction : "") +
           (withAlbedo ? kSelectionFunction : "") + body;
}

} // namespace

osg::ref_ptr<osg::Program> characterProgram(Shading shading, int order)
{
    assert(order >= 1 && order <= kMaxTransferOrder);
    osg::ref_ptr<osg::Program> program;
    switch (shading) {
    case Shading::Prt:
        program = makeProgram("thespis-prt-" + std::to_string(order), prtVertexSource(order),
                              fragmentSource(kPrtFragment, true));
        break;
    case Shading::Phong:
        program = makeProgram("thespis-phong", kWorldVertex, fragmentSource(kPhongFragment, true));
        break;
    case Shading::Unlit:
        program = makeProgram("thespis-unlit", kWorldVertex, fragmentSource(kUnlitFragment, true));
        break;
    }
    program->addBindAttribLocation("a_texcoord", kTexcoordLocation);
    for (int a = 0; a < transferAttributeCount(order); ++a)
        program->addBindAttribLocation(transferName(a), kFirstTransferLocation + unsigned(a));
    return program;
}

osg::ref_ptr<osg::Program> groundProgram()
{
    return makeProgram("thespis-ground", kWorldVertex, fragmentSource(kGroundFragment, false));
}

osg::ref_ptr<osg::Program> shadowCatcherProgram()
{
    return makeProgram("thespis-shadow-catcher", kShadowCatcherVertex, kShadowCatcherFragment);
}

osg::ref_ptr<osg::Program> depthOnlyProgram()
{
    return makeProgram("thespis-depth-only", kDepthOnlyVertex, kDepthOnlyFragment);
}

osg::ref_ptr<osg::Program> backgroundProgram()
{
    return makeProgram("thespis-background", kBackgroundVertex, fragmentSource(kBackgroundFragment, false));
}

} // namespace thespis::core::render::shaders
