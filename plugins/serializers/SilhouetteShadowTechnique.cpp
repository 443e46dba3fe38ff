// The .osgt/.osgb/.osgx wrapper of osgShadowSilhouette::SilhouetteShadowTechnique.
//
// One line per property, in the order of the class's header. Every property is read through
// a checked serializer: out-of-range values and unknown enum names are reported naming the
// property and the value, and the setter's clamped value is kept.
//
// Adding a property: add its line here (at the end, so older .osgb files keep their layout
// up to the new property) and a row to tests/cpu/test_serializer.cpp.
#include "CheckedSerializers.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/OutputStream>

REGISTER_OBJECT_WRAPPER(osgShadowSilhouette_SilhouetteShadowTechnique,
                        new osgShadowSilhouette::SilhouetteShadowTechnique,
                        osgShadowSilhouette::SilhouetteShadowTechnique,
                        "osg::Object osgShadow::ShadowTechnique osgShadowSilhouette::SilhouetteShadowTechnique")
{
    OSS_BEGIN_ENUM_PROPERTY(Mode, SHADOW_MAP);
        ADD_ENUM_VALUE(SHADOW_MAP);
        ADD_ENUM_VALUE(SILHOUETTE_MAP);
        ADD_ENUM_VALUE(HYBRID);
        ADD_ENUM_VALUE(SHADOW_VOLUME);
        serializer->setParser(&MyClass::modeFromName); // also "shadowmap", "silhouette", "hybrid", "volume"
    END_ENUM_SERIALIZER();

    OSS_ADD_PROPERTY(unsigned int, ShadowMapSize, 2048u);
    OSS_ADD_PROPERTY(float, PolygonOffsetFactor, -1.0f); // automatic
    OSS_ADD_PROPERTY(float, PolygonOffsetUnits, 4.0f);
    OSS_ADD_PROPERTY(int, LightNum, -1);
    OSS_ADD_PROPERTY(unsigned int, MaxShadowLights, 4u);
    OSS_ADD_PROPERTY(unsigned int, BaseTextureUnit, 8u);
    OSS_ADD_PROPERTY(bool, UseDefaultShading, true);

    OSS_BEGIN_ENUM_PROPERTY(DebugView, DEBUG_NONE);
        ADD_ENUM_VALUE(DEBUG_NONE);
        ADD_ENUM_VALUE(DEBUG_SHADOW_MASK);
        ADD_ENUM_VALUE(DEBUG_SILHOUETTE_PIXELS);
        ADD_ENUM_VALUE(DEBUG_SILHOUETTE_MAP);
        ADD_ENUM_VALUE(DEBUG_CLASSES);
    END_ENUM_SERIALIZER();

    OSS_ADD_PROPERTY(unsigned int, DebugLight, 0u);
    OSS_ADD_PROPERTY(bool, BlockerCulling, true);

    OSS_BEGIN_ENUM_PROPERTY(HybridMethod, HYBRID_AUTO);
        ADD_ENUM_VALUE(HYBRID_AUTO);
        ADD_ENUM_VALUE(HYBRID_STENCIL_VOLUMES);
        ADD_ENUM_VALUE(HYBRID_TRIANGLE_LISTS);
    END_ENUM_SERIALIZER();

    OSS_ADD_PROPERTY(bool, HybridEdgeMask, true);

    OSS_BEGIN_ENUM_PROPERTY(DepthPrepass, DEPTH_PREPASS_AUTO);
        ADD_ENUM_VALUE(DEPTH_PREPASS_AUTO);
        ADD_ENUM_VALUE(DEPTH_PREPASS_ON);
        ADD_ENUM_VALUE(DEPTH_PREPASS_OFF);
    END_ENUM_SERIALIZER();

    OSS_ADD_PROPERTY(float, ShadowRayOffset, 1e-6f);
    OSS_ADD_PROPERTY(bool, PerPixelLighting, true);
}
