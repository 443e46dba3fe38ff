#include "GLErrors.h"

#include <cstring>

namespace osshar {

void GLErrorCounter::notify(osg::NotifySeverity severity, const char* message)
{
    if (message && std::strstr(message, "OpenGL error")) ++_count;
    _forward->notify(severity, message);
}

GLErrorCounter& installGLErrorCounter()
{
    static osg::ref_ptr<GLErrorCounter> counter = [] {
        osg::ref_ptr<GLErrorCounter> c = new GLErrorCounter;
        osg::setNotifyHandler(c.get());
        return c;
    }();
    return *counter;
}

} // namespace osshar
