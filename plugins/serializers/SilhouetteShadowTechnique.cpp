// The .osgt/.osgb/.osgx wrapper of osgShadowSilhouette::SilhouetteShadowTechnique: one
// serializer per row of the table of properties (osgShadowSilhouette/Properties), in the
// table's order. A property added to the table is serialized without an edit here.
#include "PropertySerializer.h"

#include <osgShadowSilhouette/Properties>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osgDB/ObjectWrapper>

REGISTER_OBJECT_WRAPPER(osgShadowSilhouette_SilhouetteShadowTechnique,
                        new osgShadowSilhouette::SilhouetteShadowTechnique,
                        osgShadowSilhouette::SilhouetteShadowTechnique,
                        "osg::Object osgShadow::ShadowTechnique osgShadowSilhouette::SilhouetteShadowTechnique")
{
    for (const osgShadowSilhouette::PropertyInfo& property : osgShadowSilhouette::properties())
        wrapper->addSerializer(new ossdb::PropertySerializer(property), ossdb::PropertySerializer::typeOf(property));
}
