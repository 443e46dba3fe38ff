#include <osgShadowSilhouette/Version>

#define OSS_STR2(x) #x
#define OSS_STR(x) OSS_STR2(x)

extern "C" {

const char* osgShadowSilhouetteGetVersion()
{
    return OSS_STR(OSGSHADOWSILHOUETTE_MAJOR_VERSION) "." OSS_STR(OSGSHADOWSILHOUETTE_MINOR_VERSION) "." OSS_STR(
        OSGSHADOWSILHOUETTE_PATCH_VERSION);
}

const char* osgShadowSilhouetteGetLibraryName()
{
    return "osgShadowSilhouette Library";
}

}
