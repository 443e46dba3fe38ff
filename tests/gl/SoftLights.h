// Shared by the GL tests of soft shadows: the default scene under the lights of the soft
// benchmark (MEASURE.md, "Soft shadows").
#ifndef OSS_TESTS_GL_SOFTLIGHTS_H
#define OSS_TESTS_GL_SOFTLIGHTS_H

#include "RenderOptions.h"

#include <string>

namespace osstest {

/** The default scene lit by "sun" (its own sun), "point" (a point light at (-3, -4, 9)) or
 *  "spot" (the same, a 40-degree cone toward (0.3, 0.4, -0.9)). */
inline osshar::RenderOptions softLightOptions(const std::string& light)
{
    osshar::RenderOptions options; // the default scene, its sun
    osshar::LightArg arg;
    if (light == "sun") return options;
    arg.directional = false;
    arg.vector = osg::Vec3d(-3.0, -4.0, 9.0);
    if (light == "spot")
    {
        arg.spotDirection = osg::Vec3d(0.3, 0.4, -0.9);
        arg.spotCutoff = 40.0;
    }
    options.lights.push_back(arg);
    return options;
}

} // namespace osstest

#endif
