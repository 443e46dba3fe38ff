// Internal: reports the programs that fail to link, once each, as osg::WARN.
#ifndef OSGSHADOWSILHOUETTE_PROGRAMLINKCHECK_H
#define OSGSHADOWSILHOUETTE_PROGRAMLINKCHECK_H

#include <OpenThreads/Mutex>
#include <osg/Drawable>
#include <osg/Program>
#include <osg/observer_ptr>

#include <set>
#include <utility>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** A drawable that draws nothing. Drawn after everything else of a frame (a late render
 *  bin of the eye pass), it looks at the variants (one per define set) of each watched
 *  program linked in the drawing context so far, and reports the first that failed, once
 *  per program and context, as an osg::WARN that names the program and holds the GL info
 *  log. OSG itself reports link failures at INFO only. The check reads the link status OSG
 *  keeps (no GL query); only a failure's log is read from GL, once. */
class ProgramLinkCheck : public osg::Drawable
{
public:
    /** The render bin it is drawn in: after the eye pass's bins (the volumes' 5 and up, the
     *  transparent 10). */
    static constexpr int RENDER_BIN = 1 << 20;

    ProgramLinkCheck();
    ProgramLinkCheck(const ProgramLinkCheck&, const osg::CopyOp&);
    osg::Object* cloneType() const override { return new ProgramLinkCheck; }
    osg::Object* clone(const osg::CopyOp& op) const override { return new ProgramLinkCheck(*this, op); }
    const char* libraryName() const override { return "osgShadowSilhouette"; }
    const char* className() const override { return "ProgramLinkCheck"; }

    /** Watches `program` (not owned; null ignored; thread safe). */
    void watch(osg::Program* program);

    /** The state set that puts it into its late bin. */
    osg::StateSet* getCheckStateSet() const { return _stateSet.get(); }

    void drawImplementation(osg::RenderInfo& info) const override;
    /** No bounds: a check, not geometry (it takes no part in near/far). */
    osg::BoundingBox computeBoundingBox() const override { return osg::BoundingBox(); }

    /** A variant of `program` (one define set) that has failed to link in context
     *  `contextID`, or null. */
    static const osg::Program::PerContextProgram* linkFailure(const osg::Program& program, unsigned int contextID);

private:
    osg::ref_ptr<osg::StateSet> _stateSet;
    mutable OpenThreads::Mutex _mutex;
    std::vector<osg::observer_ptr<osg::Program>> _programs;
    mutable std::set<std::pair<const osg::Program*, unsigned int>> _reported; // (program, context)
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
