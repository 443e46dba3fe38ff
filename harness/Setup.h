// From a RenderOptions to a scene ready to render: the model, its lights, the view, the
// shadow technique, and the matching reference camera and lights.
#ifndef OSS_HARNESS_SETUP_H
#define OSS_HARNESS_SETUP_H

#include "RenderOptions.h"
#include "Scenes.h"
#include "reference/Reference.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

namespace osshar {

/** The model with its lights placed, and the view to render it from. */
struct PreparedScene
{
    osg::ref_ptr<osg::Group> content;        ///< the model and its light sources
    View view;
    std::vector<LightInScene> lights;        ///< in GL light-number order of creation
    osg::ref_ptr<osgShadowSilhouette::SilhouetteShadowTechnique> fileTechnique; ///< when the file held one
    /** The file's ShadowedScene's traversal masks (osgShadow's serializer keeps them), when
     *  the file held one: the rendered ShadowedScene takes them over. */
    unsigned int castsMask = ~0u, receivesMask = ~0u;

    /** The traversal mask the reference walks: casters and receivers both (a caster that
     *  does not receive is not drawn in the eye pass, yet still casts). */
    unsigned int referenceTraversalMask() const { return castsMask | receivesMask; }
};

/** Loads options.file (or builds options.scene), unwraps a ShadowedScene, applies
 *  --light-dir/--light-pos (light i replaces the i-th light of the scene, or is added) and
 *  adds a directional light when the scene has none. The view is the options', else the
 *  built-in scene's, else osgviewer's home view. False with a message on failure. */
bool prepareScene(const RenderOptions& options, PreparedScene& scene, std::string& error);

/** The root to render for a mode: our technique in a ShadowedScene (technique set), the
 *  content alone for "none", an osgShadow peer ("osgShadow:ShadowMap", ...) in the
 *  measurement setup of Peers.h (technique null). False with a message for an unknown mode. */
bool makeShadowedRoot(const std::string& mode, unsigned int mapSize, PreparedScene& scene,
                      osg::ref_ptr<osg::Node>& root,
                      osg::ref_ptr<osgShadowSilhouette::SilhouetteShadowTechnique>& technique, std::string& error);

/** The reference camera and light matching a view and a light of the scene. */
ossref::Camera referenceCamera(const View& view, int width, int height);
ossref::Light referenceLight(const LightInScene& light);

} // namespace osshar

#endif
