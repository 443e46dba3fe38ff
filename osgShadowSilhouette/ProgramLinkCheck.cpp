#include "ProgramLinkCheck.h"

#include <OpenThreads/ScopedLock>
#include <osg/Notify>
#include <osg/State>

#include <algorithm>
#include <iterator>

namespace osgShadowSilhouette {
namespace detail {

namespace {

/** The per-context objects of a program: osg::Program keeps them protected, and a derived
 *  class may name the member (not reach it through another object otherwise). */
struct ProgramObjectsOf : public osg::Program
{
    static const osg::Program::ProgramObjects* get(const osg::Program& program, unsigned int contextID)
    {
        const auto& list = program.*(&ProgramObjectsOf::_pcpList);
        return contextID < list.size() ? list[contextID].get() : nullptr;
    }
};

std::string programName(const osg::Program& program)
{
    return program.getName().empty() ? std::string("(unnamed)") : "\"" + program.getName() + "\"";
}

/** A define string ("#define A 1\n#define B\n") as "A 1, B". */
std::string defineList(const std::string& defines)
{
    std::string list, line;
    for (std::size_t begin = 0; begin < defines.size();)
    {
        std::size_t end = defines.find('\n', begin);
        if (end == std::string::npos) end = defines.size();
        line = defines.substr(begin, end - begin);
        begin = end + 1;
        const std::string keyword = "#define ";
        if (line.compare(0, keyword.size(), keyword) == 0) line.erase(0, keyword.size());
        if (line.empty()) continue;
        list += (list.empty() ? "" : ", ") + line;
    }
    return list;
}

} // namespace

ProgramLinkCheck::ProgramLinkCheck() : _stateSet(new osg::StateSet)
{
    setUseDisplayList(false);
    setCullingActive(false);
    setDataVariance(osg::Object::DYNAMIC);
    _stateSet->setRenderBinDetails(RENDER_BIN, "RenderBin");
}

ProgramLinkCheck::ProgramLinkCheck(const ProgramLinkCheck& check, const osg::CopyOp& op)
    : osg::Drawable(check, op), _stateSet(check._stateSet)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(check._mutex);
    _programs = check._programs;
}

void ProgramLinkCheck::watch(osg::Program* program)
{
    if (!program) return;
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    // Programs gone since are dropped here, so the list does not grow with them.
    _programs.erase(std::remove_if(_programs.begin(), _programs.end(),
                                   [](const osg::observer_ptr<osg::Program>& p) { return !p.valid(); }),
                    _programs.end());
    // Nor do the reports of programs gone: a new program at the same address is checked.
    for (auto it = _reported.begin(); it != _reported.end();)
        it = std::any_of(_programs.begin(), _programs.end(), [&](const auto& p) { return p == it->first; })
                 ? std::next(it)
                 : _reported.erase(it);
    for (const auto& p : _programs)
        if (p == program) return;
    _programs.push_back(program);
}

const osg::Program::PerContextProgram* ProgramLinkCheck::linkFailure(const osg::Program& program,
                                                                   unsigned int contextID)
{
    const osg::Program::ProgramObjects* objects = ProgramObjectsOf::get(program, contextID);
    if (!objects) return nullptr; // not applied in this context yet
    // A variant that has been through linkProgram() and is not linked failed; one still
    // waiting for its link is looked at again in a later frame.
    for (const auto& pcp : objects->_perContextPrograms)
        if (pcp && !pcp->needsLink() && !pcp->isLinked()) return pcp.get();
    return nullptr;
}

void ProgramLinkCheck::drawImplementation(osg::RenderInfo& info) const
{
    const osg::State* state = info.getState();
    if (!state) return;
    const unsigned int contextID = state->getContextID();
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (const auto& watched : _programs)
    {
        osg::ref_ptr<osg::Program> program;
        if (!watched.lock(program) || _reported.count(std::make_pair(program.get(), contextID))) continue;
        // The first failure only: the variants of a program (its define sets change with the
        // mode and the lights) mostly fail alike.
        const osg::Program::PerContextProgram* failure = linkFailure(*program, contextID);
        if (!failure) continue;
        _reported.insert(std::make_pair(program.get(), contextID));
        std::string log;
        failure->getInfoLog(log);
        OSG_WARN << "osgShadowSilhouette: program " << programName(*program) << " failed to link (context "
                 << contextID << ", defines: " << defineList(failure->getDefineString()) << "); its info log:\n"
                 << log << std::endl;
    }
}

} // namespace detail
} // namespace osgShadowSilhouette
