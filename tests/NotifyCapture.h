// Collects what OSG reports (osg::notify at every level) while it lives, so that tests can
// assert on warnings.
#ifndef OSS_TESTS_NOTIFYCAPTURE_H
#define OSS_TESTS_NOTIFYCAPTURE_H

#include <osg/Notify>
#include <osg/ref_ptr>

#include <mutex>
#include <string>

namespace osstest {

class NotifyCapture
{
public:
    NotifyCapture() : _handler(new Handler), _previous(osg::getNotifyHandler())
    {
        osg::setNotifyHandler(_handler.get());
    }
    ~NotifyCapture() { osg::setNotifyHandler(_previous.get()); }
    NotifyCapture(const NotifyCapture&) = delete;
    NotifyCapture& operator=(const NotifyCapture&) = delete;

    /** Everything reported at WARN or more severe so far. */
    std::string warnings() const
    {
        std::lock_guard<std::mutex> lock(_handler->mutex);
        return _handler->warnings;
    }
    bool warned(const std::string& part) const { return warnings().find(part) != std::string::npos; }
    /** How many times @p part occurs in warnings(). */
    int count(const std::string& part) const
    {
        const std::string all = warnings();
        int n = 0;
        for (std::size_t at = all.find(part); at != std::string::npos; at = all.find(part, at + part.size())) ++n;
        return n;
    }

private:
    struct Handler : public osg::NotifyHandler
    {
        void notify(osg::NotifySeverity severity, const char* message) override
        {
            if (severity > osg::WARN) return;
            std::lock_guard<std::mutex> lock(mutex);
            warnings += message;
        }
        mutable std::mutex mutex;
        std::string warnings;
    };
    osg::ref_ptr<Handler> _handler;
    osg::ref_ptr<osg::NotifyHandler> _previous;
};

} // namespace osstest

#endif
