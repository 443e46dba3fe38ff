// Internal: the visitors that measure the shadowed scene for a frame (bounds without
// non-finite geometry, the casters' signature and parts) and tag textured state sets.
#ifndef OSGSHADOWSILHOUETTE_SCENEVISITORS_H
#define OSGSHADOWSILHOUETTE_SCENEVISITORS_H

#include <osgShadowSilhouette/CasterEdges>
#include <osgShadowSilhouette/LightSpace>
#include <osgShadowSilhouette/MeshCache>
#include <osgShadowSilhouette/ShaderConstants>
#include <osgShadowSilhouette/ViewPoint>

#include <osg/Billboard>
#include <osg/ComputeBoundsVisitor>
#include <osg/LOD>
#include <osgShadow/ShadowedScene>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** World bounds of the drawables under the traversal mask, leaving out (and listing) the
 *  geometry with NaN or infinite vertices, which neither casts nor bounds anything. LOD
 *  children and billboard drawables are those @p view draws, turned as it turns them
 *  (each instance's matrix recorded in `billboards`). */
class FiniteBoundsVisitor : public osg::ComputeBoundsVisitor
{
public:
    FiniteBoundsVisitor(MeshCache& cache, const ViewPoint& view) : _cache(cache), _view(view) {}
    std::vector<const osg::Drawable*> nonFinite;
    BillboardMatrices billboards;

    void apply(osg::LOD& lod) override
    {
        if (!_view.valid) return traverse(lod);
        const osg::Matrixd world = current();
        for (unsigned int i = 0; i < lod.getNumChildren(); ++i)
            if (_view.isActive(lod, i, world)) lod.getChild(i)->accept(*this);
    }
    void apply(osg::Billboard& billboard) override
    {
        const osg::Matrixd world = current();
        for (unsigned int i = 0; i < billboard.getNumDrawables(); ++i)
        {
            osg::Drawable* drawable = billboard.getDrawable(i);
            if (!drawable || !validNodeMask(*drawable)) continue;
            osg::Matrix turned = _view.billboardMatrix(billboard, i, world);
            billboards[drawable].push_back(turned);
            pushMatrix(turned);
            apply(*drawable);
            popMatrix();
        }
    }

    void apply(osg::Drawable& drawable) override
    {
        const osg::Geometry* geometry = drawable.asGeometry();
        if (geometry && !_cache.hasFiniteVertices(*geometry))
            nonFinite.push_back(&drawable);
        else
            osg::ComputeBoundsVisitor::apply(drawable);
    }

private:
    osg::Matrixd current() const { return _matrixStack.empty() ? osg::Matrixd() : osg::Matrixd(_matrixStack.back()); }

    MeshCache& _cache;
    ViewPoint _view;
};

/** World bounds of the casters and a hash of what a depth pass draws of them: each
 *  drawable, its world matrix and the versions of its vertex array and primitive sets. */
class CasterSignatureVisitor : public FiniteBoundsVisitor
{
public:
    CasterSignatureVisitor(MeshCache& cache, const ViewPoint& view) : FiniteBoundsVisitor(cache, view), _meshCache(cache) {}
    std::size_t signature = 0;
    std::vector<CasterPart> parts; ///< each finite drawable: world box, and its plane when flat

    void apply(osg::Drawable& drawable) override
    {
        FiniteBoundsVisitor::apply(drawable);
        addPart(drawable);
        mix(std::hash<const void*>()(&drawable));
        if (!_matrixStack.empty())
            for (int i = 0; i < 16; ++i) mix(std::hash<double>()(_matrixStack.back().ptr()[i]));
        const osg::Geometry* geometry = drawable.asGeometry();
        if (!geometry) return;
        if (drawnMovedOnGpu(getNodePath(), *geometry)) mixUniforms();
        if (const osg::Array* vertices = geometry->getVertexArray())
        {
            mix(std::hash<const void*>()(vertices));
            mix(vertices->getModifiedCount());
        }
        for (const auto& primitives : geometry->getPrimitiveSetList())
        {
            mix(std::hash<const void*>()(primitives.get()));
            mix(primitives->getModifiedCount());
        }
    }

    void mix(std::size_t value) { signature ^= value + 0x9e3779b97f4a7c15ull + (signature << 6) + (signature >> 2); }

private:
    /** A caster moved by its vertex stage moves when a uniform on its path changes (the
     *  bones' matrix palette of hardware skinning), its arrays and matrices unchanged: each
     *  uniform's version takes part in the signature, so that no light pass is kept. */
    void mixUniforms()
    {
        for (const osg::Node* node : getNodePath())
            if (const osg::StateSet* ss = node->getStateSet())
                for (const auto& entry : ss->getUniformList())
                {
                    mix(std::hash<const void*>()(entry.second.first.get()));
                    mix(entry.second.first->getModifiedCount());
                }
    }

    void addPart(const osg::Drawable& drawable)
    {
        const osg::Geometry* geometry = drawable.asGeometry();
        if (geometry && !_meshCache.hasFiniteVertices(*geometry)) return; // left out, as from the bounds
        const osg::BoundingBox& local = drawable.getBoundingBox();
        if (!local.valid()) return;
        const osg::Matrixd world = _matrixStack.empty() ? osg::Matrixd() : _matrixStack.back();
        CasterPart part;
        for (unsigned int i = 0; i < 8; ++i) part.box.expandBy(osg::Vec3d(local.corner(i)) * world);
        std::array<osg::Vec3d, 3> spanning;
        if (geometry && _meshCache.getPlane(*geometry, spanning))
        {
            for (osg::Vec3d& p : spanning) p = p * world;
            osg::Vec3d normal = (spanning[1] - spanning[0]) ^ (spanning[2] - spanning[0]);
            if (normal.normalize() > 0.0 && std::isfinite(normal.x()) && std::isfinite(normal.y()) &&
                std::isfinite(normal.z()))
            {
                part.flat = true;
                part.planePoint = spanning[0];
                part.planeNormal = normal;
            }
        }
        parts.push_back(part);
    }

    MeshCache& _meshCache;
};

/** Tags the scene's StateSets for the technique's shaders: OSS_BASE_TEXTURE where unit 0
 *  carries a texture (the receiver shading samples it), and OSS_ALPHA_TEST with the same
 *  value as the StateSet's GL_ALPHA_TEST mode (ON or OFF, OVERRIDE and PROTECTED alike, so
 *  the define is inherited exactly as the mode is), so the depth passes output the alpha an
 *  osg::AlphaFunc tests. Records the alpha-tested drawables (GL_ALPHA_TEST on along their
 *  path, as far as the StateSets on that path say) for the warning of the stencil modes. */
class TagShaderDefinesVisitor : public osg::NodeVisitor
{
public:
    TagShaderDefinesVisitor() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Node& node) override
    {
        const AlphaTest saved = _alphaTest;
        tag(node.getStateSet());
        traverse(node);
        _alphaTest = saved;
    }
    void apply(osg::Drawable& drawable) override
    {
        const AlphaTest saved = _alphaTest;
        tag(drawable.getStateSet());
        if (_alphaTest.on) alphaTested.push_back(&drawable);
        _alphaTest = saved;
    }

    std::vector<osg::ref_ptr<osg::Drawable>> alphaTested; ///< drawables under GL_ALPHA_TEST ON

private:
    struct AlphaTest
    {
        bool on = false;
        bool overridden = false;
    };

    void tag(osg::StateSet* ss)
    {
        if (!ss) return;
        const osg::StateAttribute* tex = ss->getTextureAttribute(0, osg::StateAttribute::TEXTURE);
        if (tex && (ss->getTextureMode(0, GL_TEXTURE_2D) & osg::StateAttribute::ON))
            ss->setDefine(shader::DEFINE_BASE_TEXTURE);
        const osg::StateAttribute::GLModeValue mode = ss->getMode(GL_ALPHA_TEST);
        if (mode == osg::StateAttribute::INHERIT) return;
        ss->setDefine(shader::DEFINE_ALPHA_TEST, mode);
        if (_alphaTest.overridden && !(mode & osg::StateAttribute::PROTECTED)) return;
        _alphaTest.on = (mode & osg::StateAttribute::ON) != 0;
        _alphaTest.overridden = (mode & osg::StateAttribute::OVERRIDE) != 0;
    }

    AlphaTest _alphaTest;
};

/** World bounds of the shadowed scene's drawables under @p mask, as @p view sees them,
 *  without geometry with non-finite vertices. */
osg::BoundingBoxd boundsOf(osgShadow::ShadowedScene& scene, unsigned int mask, MeshCache& cache, const ViewPoint& view);

} // namespace detail
} // namespace osgShadowSilhouette

#endif
