// Counting the OpenGL errors OSG reports while a scene renders.
#ifndef OSS_HARNESS_GLERRORS_H
#define OSS_HARNESS_GLERRORS_H

#include <osg/Notify>
#include <osg/ref_ptr>

#include <atomic>

namespace osshar {

/** A notify handler that passes every message on to OSG's standard handler and counts those
 *  reporting an OpenGL error ("... detected OpenGL error ..." from osg::State::checkGLErrors,
 *  which OSG calls after each render bin, or after each attribute with
 *  osg::State::ONCE_PER_ATTRIBUTE). */
class GLErrorCounter : public osg::NotifyHandler
{
public:
    void notify(osg::NotifySeverity severity, const char* message) override;
    long long count() const { return _count.load(); }
    void reset() { _count = 0; }

private:
    osg::ref_ptr<osg::StandardNotifyHandler> _forward = new osg::StandardNotifyHandler;
    std::atomic<long long> _count{0};
};

/** Installs a GLErrorCounter as OSG's notify handler (once per process) and returns it. */
GLErrorCounter& installGLErrorCounter();

} // namespace osshar

#endif
