// Shared by the GL tests of casters that their own vertex shaders move: a fragment stage that
// outputs the colour, and the fixed bound such a drawable must carry.
#ifndef OSS_TESTS_MOVEDCASTERS_H
#define OSS_TESTS_MOVEDCASTERS_H

#include <osg/BoundingBox>
#include <osg/Drawable>

namespace osstest {

/** The fragment stage of the moving programs: the primary colour. */
inline const char* const PLAIN_FRAGMENT = R"(#version 400 compatibility
void main() { gl_FragColor = gl_Color; }
)";

/** A bound that holds every pose of a drawable moved by its vertex shader, computed once, as
 *  OSG's culling and the technique's light frusta need (osgAnimation's
 *  RigComputeBoundingBoxCallback gives a skinned drawable one). */
struct FixedBound : public osg::Drawable::ComputeBoundingBoxCallback
{
    explicit FixedBound(const osg::BoundingBox& b) : box(b) {}
    osg::BoundingBox computeBound(const osg::Drawable&) const override { return box; }
    osg::BoundingBox box;
};

} // namespace osstest

#endif
