#include "AnimatedScenes.h"
#include "Meshes.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/MatrixTransform>
#include <osg/ValueObject>
#include <osg/NodeVisitor>
#include <osgAnimation/BasicAnimationManager>
#include <osgAnimation/Bone>
#include <osgAnimation/Channel>
#include <osgAnimation/MorphGeometry>
#include <osgAnimation/RigGeometry>
#include <osgAnimation/RigTransformHardware>
#include <osgAnimation/Skeleton>
#include <osgAnimation/StackedRotateAxisElement>
#include <osgAnimation/StackedTranslateElement>
#include <osgAnimation/UpdateBone>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace osshar {

namespace {

const unsigned int TUBE_SIDES = 24, TUBE_RINGS = 24;
const float TUBE_RADIUS = 0.35f, TUBE_HEIGHT = 3.0f;
const int BONES = 3; // bone i stands at height i: it bends the tube from there up

/** A tube along +z from the origin, radius TUBE_RADIUS, height TUBE_HEIGHT, in TUBE_RINGS
 *  segments, closed by a fan at each end (closed and welded: vertex k of ring j is
 *  j * TUBE_SIDES + k, then the bottom and the top centre). */
osg::ref_ptr<osg::Geometry> makeTube()
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array, n = new osg::Vec3Array;
    for (unsigned int j = 0; j <= TUBE_RINGS; ++j)
        for (unsigned int k = 0; k < TUBE_SIDES; ++k)
        {
            const double a = 2.0 * M_PI * k / TUBE_SIDES;
            const osg::Vec3 radial(float(std::cos(a)), float(std::sin(a)), 0.0f);
            v->push_back(radial * TUBE_RADIUS + osg::Vec3(0, 0, TUBE_HEIGHT * j / TUBE_RINGS));
            n->push_back(radial);
        }
    const unsigned int bottom = v->size(), top = bottom + 1;
    v->push_back(osg::Vec3(0, 0, 0)), n->push_back(osg::Vec3(0, 0, -1));
    v->push_back(osg::Vec3(0, 0, TUBE_HEIGHT)), n->push_back(osg::Vec3(0, 0, 1));
    osg::ref_ptr<osg::DrawElementsUInt> tris = new osg::DrawElementsUInt(GL_TRIANGLES);
    const auto at = [](unsigned int j, unsigned int k) { return j * TUBE_SIDES + k % TUBE_SIDES; };
    for (unsigned int k = 0; k < TUBE_SIDES; ++k)
    {
        for (unsigned int j = 0; j < TUBE_RINGS; ++j)
            for (unsigned int i : {at(j, k), at(j, k + 1), at(j + 1, k + 1), at(j, k), at(j + 1, k + 1), at(j + 1, k)})
                tris->push_back(i);
        for (unsigned int i : {bottom, at(0, k + 1), at(0, k), top, at(TUBE_RINGS, k), at(TUBE_RINGS, k + 1)})
            tris->push_back(i);
    }
    g->setVertexArray(v.get());
    g->setNormalArray(n.get(), osg::Array::BIND_PER_VERTEX);
    g->addPrimitiveSet(tris.get());
    return g;
}

std::string boneName(int i)
{
    return "bone " + std::to_string(i);
}

/** Each tube vertex split between the two bones nearest its height (bone i's share falls
 *  linearly from 1 at the middle of its segment [i, i + 1] to 0 at its neighbours'), so
 *  the tube bends smoothly at the joints. */
osg::ref_ptr<osgAnimation::VertexInfluenceMap> tubeInfluences(const osg::Vec3Array& vertices)
{
    osg::ref_ptr<osgAnimation::VertexInfluenceMap> map = new osgAnimation::VertexInfluenceMap;
    for (int i = 0; i < BONES; ++i) (*map)[boneName(i)].setName(boneName(i));
    for (unsigned int k = 0; k < vertices.size(); ++k)
    {
        const float s = std::clamp(vertices[k].z() - 0.5f, 0.0f, float(BONES - 1));
        const int lower = std::min(int(s), BONES - 2);
        const float upperShare = s - float(lower);
        if (upperShare < 1.0f) (*map)[boneName(lower)].push_back({k, 1.0f - upperShare});
        if (upperShare > 0.0f) (*map)[boneName(lower + 1)].push_back({k, upperShare});
    }
    return map;
}

/** A FloatLinearChannel `name` driving `target`, through the keys (time s, value). */
osg::ref_ptr<osgAnimation::FloatLinearChannel> floatChannel(const std::string& name, const std::string& target,
                                                            std::initializer_list<std::pair<double, float>> keys)
{
    osg::ref_ptr<osgAnimation::FloatLinearChannel> channel = new osgAnimation::FloatLinearChannel;
    channel->setName(name);
    channel->setTargetName(target);
    osgAnimation::FloatKeyframeContainer* container = channel->getOrCreateSampler()->getOrCreateKeyframeContainer();
    for (const auto& [time, value] : keys) container->push_back(osgAnimation::FloatKeyframe(time, value));
    return channel;
}

/** RigTransformHardware's vertex stage: MAX_MATRIX is replaced by the palette's size;
 *  boneWeight0 holds (palette index, weight) of up to two bones. Lit per vertex by GL light
 *  0 for the picture (the program has no fragment stage: fixed-function colour). */
const char* const SKINNING_VERTEX = R"(#version 400 compatibility
uniform mat4 matrixPalette[MAX_MATRIX];
in vec4 boneWeight0;
void main()
{
    mat4 skin = boneWeight0.y * matrixPalette[int(boneWeight0.x)] + boneWeight0.w * matrixPalette[int(boneWeight0.z)];
    vec4 position = skin * gl_Vertex;
    gl_Position = gl_ModelViewProjectionMatrix * position;
    vec3 n = normalize(gl_NormalMatrix * mat3(skin) * gl_Normal);
    vec4 l = gl_LightSource[0].position;
    vec3 toLight = normalize(l.w == 0.0 ? l.xyz : l.xyz - (gl_ModelViewMatrix * position).xyz);
    gl_FrontColor = vec4(gl_Color.rgb * (0.3 + 0.7 * max(dot(n, toLight), 0.0)), gl_Color.a);
}
)";

/** The skeleton (three bones up the z axis, bone i bending about `axes[i]`) with the
 *  skinned tube; the bones' channels are added to `animation`. */
osg::ref_ptr<osgAnimation::Skeleton> skinnedTube(osgAnimation::Animation& animation, const osg::Vec4& colour)
{
    osg::ref_ptr<osgAnimation::Skeleton> skeleton = new osgAnimation::Skeleton;
    skeleton->setDefaultUpdateCallback();
    const osg::Vec3 axes[BONES] = {osg::X_AXIS, osg::Y_AXIS, osg::X_AXIS};
    const float swing[BONES] = {0.3f, 0.45f, -0.6f}; // radians at the extremes
    osg::Group* parent = skeleton.get();
    for (int i = 0; i < BONES; ++i)
    {
        osg::ref_ptr<osgAnimation::Bone> bone = new osgAnimation::Bone(boneName(i));
        bone->setInvBindMatrixInSkeletonSpace(osg::Matrix::translate(0, 0, -float(i)));
        osg::ref_ptr<osgAnimation::UpdateBone> update = new osgAnimation::UpdateBone(boneName(i));
        update->getStackedTransforms().push_back(
            new osgAnimation::StackedTranslateElement("translate", osg::Vec3(0, 0, i == 0 ? 0.0f : 1.0f)));
        update->getStackedTransforms().push_back(new osgAnimation::StackedRotateAxisElement("bend", axes[i], 0.0));
        bone->setUpdateCallback(update.get());
        parent->addChild(bone.get());
        parent = bone.get();
        const float a = swing[i];
        animation.addChannel(floatChannel("bend", boneName(i), {{0, 0}, {1, a}, {2, 0}, {3, -a}, {4, 0}}));
    }
    osg::ref_ptr<osgAnimation::RigGeometry> rig = new osgAnimation::RigGeometry;
    rig->setName("skinned tube");
    osg::ref_ptr<osg::Geometry> source = makeTube();
    rig->setSourceGeometry(source.get());
    rig->setInfluenceMap(tubeInfluences(*static_cast<osg::Vec3Array*>(source->getVertexArray())).get());
    // After the bones: the update traversal poses them before it skins the tube.
    skeleton->addChild(coloured(rig.get(), colour).get());
    return skeleton;
}

/** A sphere whose morph target is the sphere flattened to 0.55 of its height and stretched
 *  to 1.5 of its width along x, still standing on the ground; the weight's channel is added
 *  to `animation`. */
osg::ref_ptr<osg::Geode> morphingSphere(osgAnimation::Animation& animation, const osg::Vec4& colour)
{
    const osg::Vec3 centre(2.5f, 2.5f, 1.2f);
    const float radius = 1.1f;
    osg::ref_ptr<osg::Geometry> base = makeSphere(centre, radius, 40, 20);
    osg::ref_ptr<osgAnimation::MorphGeometry> morph = new osgAnimation::MorphGeometry(*base);
    morph->setName("morphing sphere");
    osg::ref_ptr<osg::Geometry> target = makeSphere(centre, radius, 40, 20);
    osg::Vec3Array* v = static_cast<osg::Vec3Array*>(target->getVertexArray());
    const osg::Vec3 foot = centre - osg::Vec3(0, 0, radius);
    for (osg::Vec3& p : *v)
    {
        const osg::Vec3 d = p - foot;
        p = foot + osg::Vec3(1.5f * d.x(), d.y(), 0.55f * d.z());
    }
    morph->addMorphTarget(target.get(), 0.0f);
    osg::ref_ptr<osg::Geode> geode = coloured(morph.get(), colour);
    osg::ref_ptr<osgAnimation::UpdateMorph> update = new osgAnimation::UpdateMorph("morph");
    update->addTarget("morphing sphere");
    geode->setUpdateCallback(update.get());
    animation.addChannel(floatChannel("0", "morphing sphere", {{0, 0}, {2, 1}, {4, 0}}));
    return geode;
}

const unsigned int SHEET_COLUMNS = 28, SHEET_ROWS = 20;
const osg::Vec3 SHEET_CORNER(-1.0f, -4.0f, 2.3f);
const float SHEET_WIDTH = 3.5f, SHEET_DEPTH = 2.5f;

/** The sheet's height above SHEET_CORNER at (x, y) from its corner at time t: a wave of
 *  0.3 travelling along x at 0.75 units per second, rolling a little along y. */
float sheetWave(float x, float y, double t)
{
    return float(0.3 * std::sin(2.0 * M_PI * (x / 2.0 - 0.375 * t)) * (0.6 + 0.4 * std::cos(1.2 * y)));
}

/** Writes the wave of the frame's simulation time into the sheet's vertices and normals,
 *  then dirty()s both arrays and the bound, as an application editing an array does. */
class WaveSheet : public osg::DrawableUpdateCallback
{
public:
    void update(osg::NodeVisitor* nv, osg::Drawable* drawable) override
    {
        osg::Geometry* sheet = drawable->asGeometry();
        if (!sheet || !nv->getFrameStamp()) return;
        const double t = nv->getFrameStamp()->getSimulationTime();
        osg::Vec3Array* v = static_cast<osg::Vec3Array*>(sheet->getVertexArray());
        osg::Vec3Array* n = static_cast<osg::Vec3Array*>(sheet->getNormalArray());
        const float dx = SHEET_WIDTH / SHEET_COLUMNS, dy = SHEET_DEPTH / SHEET_ROWS, h = 1e-3f;
        for (unsigned int j = 0; j <= SHEET_ROWS; ++j)
            for (unsigned int i = 0; i <= SHEET_COLUMNS; ++i)
            {
                const float x = i * dx, y = j * dy;
                const unsigned int k = j * (SHEET_COLUMNS + 1) + i;
                (*v)[k] = SHEET_CORNER + osg::Vec3(x, y, sheetWave(x, y, t));
                osg::Vec3 normal(-(sheetWave(x + h, y, t) - sheetWave(x - h, y, t)) / (2 * h),
                                 -(sheetWave(x, y + h, t) - sheetWave(x, y - h, t)) / (2 * h), 1.0f);
                normal.normalize();
                (*n)[k] = normal;
            }
        v->dirty();
        n->dirty();
        sheet->dirtyBound();
    }
};

/** sheetWave() in the sheet's vertex stage, at the uniform time the update callback sets;
 *  the vertex array holds the flat sheet. */
const char* const WAVE_VERTEX = R"(#version 400 compatibility
uniform float sheetTime;
const float PI = 3.14159265358979;
float sheetWave(float x, float y)
{
    return 0.3 * sin(2.0 * PI * (x / 2.0 - 0.375 * sheetTime)) * (0.6 + 0.4 * cos(1.2 * y));
}
void main()
{
    // The sheet's own coordinates: from its corner (-1, -4, 2.3), as sheetWave() takes them.
    vec2 p = gl_Vertex.xy - vec2(-1.0, -4.0);
    vec4 position = gl_Vertex + vec4(0.0, 0.0, sheetWave(p.x, p.y), 0.0);
    gl_Position = gl_ModelViewProjectionMatrix * position;
    gl_FrontColor = gl_Color;
}
)";

/** Sets the sheet's uniform time from each update traversal's frame stamp. */
class SheetTime : public osg::UniformCallback
{
public:
    void operator()(osg::Uniform* uniform, osg::NodeVisitor* nv) override
    {
        if (nv->getFrameStamp()) uniform->set(float(nv->getFrameStamp()->getSimulationTime()));
    }
};

/** The bound of every pose of the sheet: its flat grid grown by the wave's amplitude. */
class SheetBound : public osg::Drawable::ComputeBoundingBoxCallback
{
public:
    osg::BoundingBox computeBound(const osg::Drawable&) const override
    {
        return osg::BoundingBox(SHEET_CORNER - osg::Vec3(0, 0, 0.3f),
                                SHEET_CORNER + osg::Vec3(SHEET_WIDTH, SHEET_DEPTH, 0.3f));
    }
};

/** The sheet waved by its vertex shader: the flat grid, the program, the time and the bound. */
void waveOnGpu(osg::Geometry& sheet)
{
    sheet.setUpdateCallback(nullptr);
    osg::Vec3Array* v = static_cast<osg::Vec3Array*>(sheet.getVertexArray());
    osg::Vec3Array* n = static_cast<osg::Vec3Array*>(sheet.getNormalArray());
    for (unsigned int j = 0; j <= SHEET_ROWS; ++j)
        for (unsigned int i = 0; i <= SHEET_COLUMNS; ++i)
        {
            const unsigned int k = j * (SHEET_COLUMNS + 1) + i;
            (*v)[k] = SHEET_CORNER + osg::Vec3(i * SHEET_WIDTH / SHEET_COLUMNS, j * SHEET_DEPTH / SHEET_ROWS, 0.0f);
            (*n)[k] = osg::Vec3(0, 0, 1);
        }
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName("waving sheet");
    program->setUserValue(osgShadowSilhouette::SilhouetteShadowTechnique::MOVES_VERTICES_USER_VALUE, true);
    program->addShader(new osg::Shader(osg::Shader::VERTEX, WAVE_VERTEX));
    osg::StateSet* ss = sheet.getOrCreateStateSet();
    ss->setAttributeAndModes(program.get());
    osg::ref_ptr<osg::Uniform> time = new osg::Uniform("sheetTime", 0.0f);
    time->setUpdateCallback(new SheetTime);
    ss->addUniform(time.get());
    sheet.setComputeBoundingBoxCallback(new SheetBound);
    sheet.dirtyBound();
}

/** The tube skinned by RigTransformHardware with SKINNING_VERTEX. */
void skinOnGpu(osgAnimation::RigGeometry& rig)
{
    osg::ref_ptr<osgAnimation::RigTransformHardware> skinning = new osgAnimation::RigTransformHardware;
    skinning->setShader(new osg::Shader(osg::Shader::VERTEX, SKINNING_VERTEX));
    rig.setRigTransformImplementation(skinning.get());
}

osg::ref_ptr<osg::Geometry> wavingSheet()
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setName("waving sheet");
    const unsigned int count = (SHEET_COLUMNS + 1) * (SHEET_ROWS + 1);
    g->setVertexArray(new osg::Vec3Array(count));
    g->setNormalArray(new osg::Vec3Array(count), osg::Array::BIND_PER_VERTEX);
    osg::ref_ptr<osg::DrawElementsUInt> tris = new osg::DrawElementsUInt(GL_TRIANGLES);
    for (unsigned int j = 0; j < SHEET_ROWS; ++j)
        for (unsigned int i = 0; i < SHEET_COLUMNS; ++i)
        {
            const unsigned int k = j * (SHEET_COLUMNS + 1) + i, up = k + SHEET_COLUMNS + 1;
            for (unsigned int c : {k, k + 1, up + 1, k, up + 1, up}) tris->push_back(c);
        }
    g->addPrimitiveSet(tris.get());
    g->setDataVariance(osg::Object::DYNAMIC);
    g->setUseDisplayList(false);
    g->setUseVertexBufferObjects(true);
    g->setUpdateCallback(new WaveSheet);
    return g;
}

/** Plays every animation of the BasicAnimationManagers among a node's update callbacks. */
class PlayAnimationsVisitor : public osg::NodeVisitor
{
public:
    PlayAnimationsVisitor() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Node& node) override
    {
        for (osg::Callback* c = node.getUpdateCallback(); c; c = c->getNestedCallback())
            if (auto* basic = dynamic_cast<osgAnimation::BasicAnimationManager*>(c))
                for (const osg::ref_ptr<osgAnimation::Animation>& animation : basic->getAnimationList())
                {
                    animation->setPlayMode(osgAnimation::Animation::LOOP);
                    basic->playAnimation(animation.get());
                    ++started;
                }
            else if (dynamic_cast<osgAnimation::AnimationManagerBase*>(c))
                ++others;
        traverse(node);
    }
    unsigned int started = 0, others = 0;
};

} // namespace

Scene animatedScene()
{
    Scene s{"animated", new osg::Group, {}};
    s.root->setName("animated: skinned, morphed and edited casters");
    s.root->addChild(coloured(makeGround(0, 0, 16), groundColour()));
    osg::ref_ptr<osgAnimation::Animation> animation = new osgAnimation::Animation;
    animation->setName("bend and morph");
    osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(osg::Matrix::translate(-3.0f, 1.0f, 0.0f));
    placed->addChild(skinnedTube(*animation, osg::Vec4(0.8f, 0.3f, 0.25f, 1)).get());
    s.root->addChild(placed.get());
    s.root->addChild(morphingSphere(*animation, osg::Vec4(0.3f, 0.5f, 0.85f, 1)).get());
    s.root->addChild(coloured(wavingSheet(), osg::Vec4(0.85f, 0.75f, 0.3f, 1)).get());
    animation->setDuration(4.0);
    animation->setPlayMode(osgAnimation::Animation::LOOP);
    osg::ref_ptr<osgAnimation::BasicAnimationManager> manager = new osgAnimation::BasicAnimationManager;
    manager->registerAnimation(animation.get());
    s.root->setUpdateCallback(manager.get());
    s.root->addChild(makeLight(osg::Vec4(0.45f, -0.35f, 0.82f, 0.0f)));
    s.view = {osg::Vec3d(0.5, -11, 7), osg::Vec3d(0, 0, 1.0), osg::Vec3d(0, 0, 1), 40.0};
    return s;
}

unsigned int deformOnGpu(osg::Node& root)
{
    struct Mover : osg::NodeVisitor
    {
        Mover() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        void apply(osg::Geometry& g) override
        {
            auto* rig = dynamic_cast<osgAnimation::RigGeometry*>(&g);
            if (rig && rig->getName() == "skinned tube")
                skinOnGpu(*rig), ++moved;
            else if (g.getName() == "waving sheet")
                waveOnGpu(g), ++moved;
        }
        unsigned int moved = 0;
    } mover;
    root.accept(mover);
    return mover.moved;
}

unsigned int playAnimations(osg::Node* root, unsigned int* otherManagers)
{
    PlayAnimationsVisitor v;
    if (root) root->accept(v);
    if (otherManagers) *otherManagers = v.others;
    return v.started;
}

} // namespace osshar
