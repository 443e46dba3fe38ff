// Internal: the casters' own vertex stages in the light passes that draw the scene (the depth
// maps and the triangle lists), so that a caster skinned or displaced in its vertex shader
// casts the shape the eye sees.
#ifndef OSGSHADOWSILHOUETTE_CASTERVERTEXSTAGES_H
#define OSGSHADOWSILHOUETTE_CASTERVERTEXSTAGES_H

#include <OpenThreads/Mutex>
#include <osg/Program>
#include <osg/Referenced>
#include <osg/StateSet>
#include <osg/observer_ptr>
#include <osgUtil/RenderBin>

#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** A light pass draws every caster with its own program (`OVERRIDE`), whose vertex stage is
 *  ftransform(). A caster whose state (below the pass camera's) sets a program with a vertex
 *  shader, and no geometry or tessellation stage, is drawn instead with a program of that
 *  program's vertex shaders and the pass program's other stages (its fragment stage, and the
 *  lists' geometry stage), with the caster program's attribute bindings: a skinning shader
 *  (osgAnimation's RigTransformHardware) or a displacement runs in the light pass too.
 *
 *  The contract on such a vertex stage: it writes gl_Position as the compatibility
 *  profile's gl_ModelViewProjectionMatrix (or the osg_ uniforms OSG keeps equal to it) times
 *  its final object-space position, as any vertex shader drawn through an osg::Camera does.
 *  The passes' other stages read nothing else of it: the lists' geometry stage takes the
 *  light's view space from gl_Position, and the depth pass's fragment stage needs nothing
 *  (an alpha-tested caster with its own vertex stage casts its whole triangles: the cut-out
 *  needs texture coordinates the vertex stage owes no one).
 *
 *  Thread safe: the cull threads of every view share it. */
class CasterVertexStages : public osg::Referenced
{
public:
    /** @p watchLink has each program made here checked for link errors. */
    explicit CasterVertexStages(std::function<void(osg::Program*)> watchLink) : _watchLink(std::move(watchLink)) {}

    /** Moves the leaves of @p bin (and its nested bins) whose caster program has a vertex
     *  stage under a state graph child that applies the joined program (`ON | OVERRIDE |
     *  PROTECTED`, over @p passState's program, also `OVERRIDE`). Only the state sets below
     *  @p passState (the pass camera's, on every leaf's path) count: those above it belong to
     *  the eye's side of the scene graph. Returns the number of leaves moved. */
    std::size_t apply(osgUtil::RenderBin& bin, const osg::StateSet& passState);

    /** The program that decides the vertex stage of the leaves under @p graph, set below
     *  @p passState, as OSG applies programs (a higher OVERRIDE wins unless a lower one is
     *  PROTECTED), or null. */
    static const osg::Program* casterProgram(const osgUtil::StateGraph& graph, const osg::StateSet& passState);

    /** Whether the light passes can draw with @p program's vertex stage: it has a vertex
     *  shader and no geometry or tessellation stage (whose output would be what the eye sees). */
    static bool hasOwnVertexStage(const osg::Program& program);

    /** Whether @p program, drawing @p drawable, puts its vertices elsewhere than its vertex
     *  array: it has its own vertex stage and either says so
     *  (SilhouetteShadowTechnique::MOVES_VERTICES_USER_VALUE) or draws one of osgAnimation's
     *  drawables (RigTransformHardware, MorphTransformHardware). */
    static bool movesVertices(const osg::Program& program, const osg::Drawable& drawable);

    /** After a receivers' pass of the eye under @p pass: the leaves whose own program (set
     *  below @p pass) moves their vertices (movesVertices()) but that the pass draws with
     *  another (an OVERRIDE above it: the stencil modes' passes) would stand at their rest
     *  pose. The @p base pass draws them with their own program (`PROTECTED`), which shades
     *  them itself, whether or not its state overrides programs yet (a stencil mode sets its
     *  program on that state after culling it, in the first frame); every other pass (the
     *  lights' additive and mask passes) leaves them out. Returns the number of leaves moved
     *  or left out. */
    std::size_t keepMovedReceivers(osgUtil::RenderBin& bin, const osg::StateSet& pass, bool base);

    /** Joined programs held (tests). */
    std::size_t size() const;

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state = nullptr) const;

protected:
    struct Joined
    {
        osg::observer_ptr<const osg::Program> caster, pass;
        std::vector<const osg::Shader*> shaders;  ///< of both, as joined
        osg::Program::AttribBindingList bindings; ///< the caster program's, as joined
        osg::ref_ptr<osg::StateSet> stateSet;     ///< the joined program
    };
    /** The state set of @p caster's vertex stage joined to @p pass's other stages. */
    osg::StateSet* joined(const osg::Program& caster, const osg::Program& pass);
    static std::vector<const osg::Shader*> joinedShaders(const osg::Program& caster, const osg::Program& pass);
    /** The program the state sets of @p graph's path below @p top (all of them: null) apply,
     *  as OSG applies programs; @p under: whether the path reaches @p top. */
    static const osg::Program* programBelow(const osgUtil::StateGraph& graph, const osg::StateSet* top, bool& under);
    /** A state set that applies @p program `PROTECTED` (cached). */
    osg::StateSet* ownProgramState(const osg::Program& program);
    void prune();

    std::function<void(osg::Program*)> _watchLink;
    mutable OpenThreads::Mutex _mutex;
    std::map<std::pair<const osg::Program*, const osg::Program*>, Joined> _joined;
    std::vector<std::pair<osg::observer_ptr<const osg::Program>, osg::ref_ptr<osg::StateSet>>> _own;
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
