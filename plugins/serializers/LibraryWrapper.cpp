// Lets applications that link the serializers statically pull the wrappers in with
// USE_SERIALIZER_WRAPPER_LIBRARY(osgShadowSilhouette).
#include <osgDB/Registry>

USE_SERIALIZER_WRAPPER(osgShadowSilhouette_SilhouetteShadowTechnique)

extern "C" void wrapper_serializer_library_osgShadowSilhouette(void) {}
