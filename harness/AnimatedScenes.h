// The built-in scene whose casters deform every frame, and playing a scene's animations.
#ifndef OSS_HARNESS_ANIMATEDSCENES_H
#define OSS_HARNESS_ANIMATEDSCENES_H

#include "Scenes.h"

namespace osshar {

/** "animated": on a 16 x 16 ground, three casters that OSG deforms on the CPU, as
 *  applications animate characters and cloth:
 *  - "skinned tube": an osgAnimation::RigGeometry (a capped tube 3 high, skinned on the CPU
 *    by osgAnimation's default RigTransformSoftware) on an osgAnimation::Skeleton of three
 *    Bones, each bent by an UpdateBone's StackedRotateAxisElement "bend";
 *  - "morphing sphere": an osgAnimation::MorphGeometry whose one morph target (a flattened,
 *    stretched sphere) is weighted by an UpdateMorph;
 *  - "waving sheet": a plain osg::Geometry, an open 3.5 x 2.5 grid, whose update callback
 *    writes a travelling wave into its vertex array at the frame's simulation time, then
 *    dirty()s the array and the bound.
 *  One osgAnimation::BasicAnimationManager on the root holds the animation "bend and morph"
 *  (channels for the bones' angles and the morph weight, 4 s long); it plays only once
 *  playAnimations() starts it. The light is the default scene's sun. Frames rendered at
 *  explicit simulation times (Renderer::setSimulationTime()) show the same pose for the same
 *  time, run after run. */
Scene animatedScene();

/** Moves the deformation of animatedScene()'s tube and sheet (under @p root, before its first
 *  update traversal) to the GPU, as applications do to spare the CPU: the tube skinned by
 *  osgAnimation's RigTransformHardware (a vertex shader given in code, since OSG's
 *  skinning.vert is not installed; up to two bones per vertex, as the tube has), the
 *  sheet's wave computed in its vertex shader from a uniform time that an update callback
 *  sets from the frame's simulation time. Both keep their rest positions in their vertex
 *  arrays (the tube its bind pose, the sheet flat) and carry a bound that holds every pose
 *  (the sheet's ComputeBoundingBoxCallback; the rig's is osgAnimation's), as a shader's
 *  displacement needs for OSG's culling. At the same simulation times the poses are those
 *  of animatedScene(), which therefore gives the exact reference (the reference reads vertex
 *  arrays: it cannot see a GPU's positions). Returns the number of casters moved (2). */
unsigned int deformOnGpu(osg::Node& root);

/** Starts, looping from the next update traversal's time, every animation of every
 *  osgAnimation::BasicAnimationManager among the update callbacks (nested ones included) of
 *  the nodes under @p root; other osgAnimation::AnimationManagerBase kinds are counted in
 *  @p otherManagers and left alone. Returns the number of animations started. */
unsigned int playAnimations(osg::Node* root, unsigned int* otherManagers = nullptr);

} // namespace osshar

#endif
