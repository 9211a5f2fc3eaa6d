#pragma once
// The GLSL programs of the render scene (GLSL 1.20, for compatibility-profile contexts), and the
// attribute locations and uniform names they share with the C++ side. Internal to core/render.
//
// Vertex layout of characters: gl_Vertex and gl_Normal (world space), texture coordinates in
// generic attribute kTexcoordLocation, the transfer vector (order² floats, zero-padded) in
// ⌈order²/4⌉ vec4 generic attributes from kFirstTransferLocation. Locations 0 and 2 are left
// free because some drivers alias them with gl_Vertex and gl_Normal.

#include <osg/Program>
#include <osg/ref_ptr>

#include "render/shading.h"

namespace thespis::core::render::shaders {

/// The highest transfer order the character shader takes (36 coefficients in 9 vec4 attributes).
inline constexpr int kMaxTransferOrder = 6;
inline constexpr unsigned kTexcoordLocation = 1;
inline constexpr unsigned kFirstTransferLocation = 3;

constexpr int transferAttributeCount(int order) { return (order * order + 3) / 4; }

/// Character program for a shading mode. `order` sizes the PRT light array and the transfer
/// attributes (1 … kMaxTransferOrder); the other modes ignore it but bind the same attributes.
/// Uniforms: exposure; baseColor (vec4), baseColorTexture (unit 0), textureWeight (0 or 1);
/// Prt: shLight (vec3[order²]); Phong: lightDirection, lightColor, ambientIrradiance; every
/// mode: selectionHighlight (float, 0 or 1: tint the segment as selected; must be set on every
/// segment, as GL keeps a program's last value).
osg::ref_ptr<osg::Program> characterProgram(Shading shading, int order);
/// The ground: uniform groundColor (linear radiance), exposure; a faint 1 m grid.
osg::ref_ptr<osg::Program> groundProgram();
/// The shadow catcher over video: a square [−1, 1]² in x and z placed on the ground by the uniform
/// shadowArea (vec3: centre x, z, half side), shadowTexture (unit 0: the shadow over it, red
/// channel), shadowStrength; black with the shadow as alpha.
osg::ref_ptr<osg::Program> shadowCatcherProgram();
/// Phantom occluders: depth only (draw with the colour masked off).
osg::ref_ptr<osg::Program> depthOnlyProgram();
/// Full-screen environment background: probeTexture (lat-long, linear RGB), exposure.
osg::ref_ptr<osg::Program> backgroundProgram();

} // namespace thespis::core::render::shaders
