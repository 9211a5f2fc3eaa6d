#pragma once
// What the renderer draws, as one OSG graph that any viewer can host (the offscreen renderer, the
// studio's embedded viewport): characters (CharacterNode), an optional ground disc at y = 0 lit
// by the light's irradiance on its up normal, and an optional environment background drawn from
// a light probe where nothing else was drawn. The scene owns its character nodes and the skinning
// threads they share. The background colour (used where there is no probe) is the clear colour
// the hosting viewer sets. Every node draws with its own shaders, so the viewer's fixed-function
// state (head light, near/far computation) does not change the picture.

#include <array>
#include <memory>
#include <vector>

#include <osg/Group>
#include <osg/Uniform>
#include <osg/ref_ptr>

#include "lighting/probe.h"
#include "lighting/sh.h"
#include "lighting/transfer_bake.h"
#include "render/camera.h"
#include "render/character_node.h"
#include "render/shading.h"
#include "scene/character.h"
#include "scene/skinning.h"
#include "util/error.h"

namespace thespis::core::render {

class RenderScene {
public:
    /// skinningThreads as for scene::SkinningWorkers (≤ 0: one per hardware thread).
    explicit RenderScene(int skinningThreads = 0);
    ~RenderScene();
    RenderScene(const RenderScene&) = delete;
    RenderScene& operator=(const RenderScene&) = delete;

    osg::Group* root() const { return m_root.get(); }

    /// Adds a character in its rest pose with the scene's shading and light (see CharacterNode::create).
    Result<CharacterNode*> addCharacter(std::shared_ptr<const scene::Character> character,
                                        const lighting::TransferBake* bake = nullptr,
                                        scene::SkinningMethod skinning = scene::SkinningMethod::Linear);
    void clearCharacters();
    std::size_t characterCount() const { return m_characters.size(); }
    CharacterNode& character(std::size_t index) const { return *m_characters[index]; }
    /// Posed bounds of every character (empty without characters).
    Bounds characterBounds() const;

    void setShading(Shading shading);
    Shading shading() const { return m_shading; }

    /// The distant light, world frame, any order (defaultLight() until set).
    void setLight(const lighting::ShRgb& light);
    const lighting::ShRgb& light() const { return m_light; }
    /// An order-6 sky for demo renders: a blue sky dome over a darker ground, and a warm key light
    /// from above, in front of the character (+z) and to the left of a camera looking at it.
    static const lighting::ShRgb& defaultLight();

    /// Multiplies lit radiance before the sRGB encoding (1 by default).
    void setExposure(float exposure);

    /// A disc of 10 m radius at y = 0 (albedo 0.5, a faint 1 m grid); off by default.
    void setGroundVisible(bool visible);
    bool groundVisible() const;

    /// Display-referred (sRGB-encoded) colour where nothing is drawn; (0.18, 0.2, 0.23) by default.
    void setBackgroundColor(const std::array<float, 3>& color) { m_backgroundColor = color; }
    const std::array<float, 3>& backgroundColor() const { return m_backgroundColor; }
    /// Where nothing is drawn the picture is transparent (alpha 0, black): a layer to put over
    /// video. Off by default.
    void setTransparentBackground(bool transparent) { m_transparentBackground = transparent; }
    bool transparentBackground() const { return m_transparentBackground; }
    /// Shows a probe behind everything, resampled to a width × width/2 lat-long texture.
    /// `degrees` and `intensity` turn and scale it as lighting::turnedLight() does the light.
    void setBackgroundProbe(const lighting::LightProbe& probe, int width = 512, double degrees = 0, double intensity = 1);
    void clearBackgroundProbe();
    bool hasBackgroundProbe() const;

private:
    void updateGroundColor();

    std::unique_ptr<scene::SkinningWorkers> m_workers;
    std::vector<std::unique_ptr<CharacterNode>> m_characters;
    Shading m_shading = Shading::Prt;
    lighting::ShRgb m_light;
    std::array<float, 3> m_backgroundColor{0.18f, 0.2f, 0.23f};
    bool m_transparentBackground = false;

    osg::ref_ptr<osg::Group> m_root;
    osg::ref_ptr<osg::Group> m_characterGroup;
    osg::ref_ptr<osg::Node> m_ground;
    osg::ref_ptr<osg::Node> m_background;
    osg::ref_ptr<osg::Uniform> m_exposure, m_groundColor;
};

} // namespace thespis::core::render
