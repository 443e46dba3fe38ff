#include <osgShadowSilhouette/GpuQueries>
#include "GLConstants.h"

#include <osg/Depth>
#include <osg/FrameStamp>
#include <osg/GLExtensions>
#include <osg/observer_ptr>
#include <osg/State>

namespace osgShadowSilhouette {

namespace {

unsigned int frameOf(const osg::RenderInfo& info)
{
    const osg::FrameStamp* fs = info.getState() ? info.getState()->getFrameStamp() : nullptr;
    return fs ? fs->getFrameNumber() : 0u;
}

bool queriesSupported(const osg::GLExtensions* ext)
{
    return ext && ext->glGenQueries && ext->glBeginQuery && ext->glEndQuery && ext->glGetQueryObjectuiv &&
           ext->glGetQueryObjectui64v;
}

/** A drawable that only calls a function at its place in the render order. */
class CallDrawable : public osg::Drawable
{
public:
    CallDrawable(GpuCounter* counter, bool begin) : _counter(counter), _begin(begin)
    {
        setUseDisplayList(false);
        setCullingActive(false);
        setDataVariance(osg::Object::DYNAMIC);
    }
    CallDrawable(const CallDrawable& d, const osg::CopyOp& op)
        : osg::Drawable(d, op), _counter(d._counter), _begin(d._begin) {}
    osg::Object* cloneType() const override { return new CallDrawable(nullptr, true); }
    osg::Object* clone(const osg::CopyOp& op) const override { return new CallDrawable(*this, op); }
    const char* libraryName() const override { return "osgShadowSilhouette"; }
    const char* className() const override { return "GpuCounterDrawable"; }

    void drawImplementation(osg::RenderInfo& info) const override
    {
        if (!_counter) return;
        if (_begin)
            _counter->begin(info);
        else
            _counter->end(info);
    }
    // No bounds: a state change, not geometry. A box (around the origin of the frame it is
    // drawn in) would take part in the view's near/far computation and, with the scene far
    // from the origin, push the near plane past it. Culling is off for it.
    osg::BoundingBox computeBoundingBox() const override { return osg::BoundingBox(); }

private:
    osg::ref_ptr<GpuCounter> _counter;
    bool _begin;
};

/** A drawable in a node of its own, drawn in render bin `bin`. */
osg::ref_ptr<osg::Node> counterNode(osg::ref_ptr<osg::Drawable> drawable, int bin)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(drawable.get());
    geode->setCullingActive(false);
    geode->getOrCreateStateSet()->setRenderBinDetails(bin, "RenderBin");
    return geode;
}

/** Draws a caster's box inside its occlusion query. */
class IssueQueryCallback : public osg::Drawable::DrawCallback
{
public:
    IssueQueryCallback(BlockerQueries* queries, unsigned int index) : _queries(queries), _index(index) {}
    void drawImplementation(osg::RenderInfo& info, const osg::Drawable* drawable) const override
    {
        osg::ref_ptr<BlockerQueries> queries;
        if (_queries.lock(queries)) queries->issue(info, _index, drawable);
    }

private:
    osg::observer_ptr<BlockerQueries> _queries; // owns the drawable that owns this callback
    unsigned int _index;
};

/** Draws a shadow volume only where its caster's query found a sample (on the GPU). */
class ConditionalDrawCallback : public osg::Drawable::DrawCallback
{
public:
    ConditionalDrawCallback(BlockerQueries* queries, unsigned int index) : _queries(queries), _index(index) {}
    void drawImplementation(osg::RenderInfo& info, const osg::Drawable* drawable) const override
    {
        const GLuint id = _queries->issuedQuery(info, _index);
        const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
        if (id == 0 || !ext->glBeginConditionalRender || !ext->glEndConditionalRender)
        {
            drawable->drawImplementation(info);
            return;
        }
        ext->glBeginConditionalRender(id, GL_QUERY_WAIT);
        drawable->drawImplementation(info);
        ext->glEndConditionalRender();
    }

private:
    osg::ref_ptr<BlockerQueries> _queries;
    unsigned int _index;
};

} // namespace

// ---------------------------------------------------------------------------------------
// GpuCounter

GpuCounter::GpuCounter(GLenum target) : _target(target) {}

GpuCounter::~GpuCounter() = default;

osg::ref_ptr<osg::Drawable> GpuCounter::createBegin()
{
    return new CallDrawable(this, true);
}

osg::ref_ptr<osg::Drawable> GpuCounter::createEnd()
{
    return new CallDrawable(this, false);
}

osg::ref_ptr<osg::Node> GpuCounter::createBeginNode(int bin)
{
    return counterNode(createBegin(), bin);
}

osg::ref_ptr<osg::Node> GpuCounter::createEndNode(int bin)
{
    return counterNode(createEnd(), bin);
}

bool GpuCounter::atomic() const
{
    return _target == GL_ATOMIC_COUNTER_BUFFER;
}

bool GpuCounter::create(osg::RenderInfo& info, PerContext& c) const
{
    const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
    if (atomic())
    {
        if (!ext || !ext->glGenBuffers || !ext->glBindBuffer || !ext->glBufferData || !ext->glBufferSubData ||
            !ext->glGetBufferSubData || !ext->glBindBufferBase || !ext->glFenceSync || !ext->glClientWaitSync ||
            !ext->glDeleteSync || !osg::isGLExtensionOrVersionSupported(info.getContextID(),
                                                                        "GL_ARB_shader_atomic_counters", 4.2f))
            return false;
        ext->glGenBuffers(RING, c.ids);
        const GLuint zero[ATOMIC_COUNTERS] = {};
        for (GLuint id : c.ids)
        {
            ext->glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, id);
            ext->glBufferData(GL_ATOMIC_COUNTER_BUFFER, sizeof(zero), zero, GL_DYNAMIC_READ);
        }
        ext->glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, 0);
        return true;
    }
    const bool statistics = _target == GL_FRAGMENT_SHADER_INVOCATIONS_ARB;
    if (!queriesSupported(ext) ||
        (statistics && !osg::isGLExtensionSupported(info.getContextID(), "GL_ARB_pipeline_statistics_query")))
        return false;
    ext->glGenQueries(RING, c.ids);
    return true;
}

bool GpuCounter::collect(const osg::GLExtensions& ext, PerContext& c, unsigned int i, long long* values) const
{
    if (atomic())
    {
        if (ext.glClientWaitSync(c.fences[i], 0, 0) == GL_TIMEOUT_EXPIRED) return false;
        ext.glDeleteSync(c.fences[i]);
        c.fences[i] = nullptr;
        GLuint counts[ATOMIC_COUNTERS] = {};
        ext.glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, c.ids[i]);
        ext.glGetBufferSubData(GL_ATOMIC_COUNTER_BUFFER, 0, sizeof(counts), counts);
        ext.glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, 0);
        for (unsigned int k = 0; k < ATOMIC_COUNTERS; ++k) values[k] = static_cast<long long>(counts[k]);
        return true;
    }
    GLuint available = 0;
    ext.glGetQueryObjectuiv(c.ids[i], GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) return false;
    GLuint64 result = 0;
    ext.glGetQueryObjectui64v(c.ids[i], GL_QUERY_RESULT, &result);
    values[0] = static_cast<long long>(result);
    return true;
}

void GpuCounter::begin(osg::RenderInfo& info)
{
    osg::State* state = info.getState();
    const osg::GLExtensions* ext = state->get<osg::GLExtensions>();
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    PerContext& c = _contexts[info.getContextID()];
    if (c.unsupported) return;
    if (c.ids[0] == 0 && !create(info, c))
    {
        c.unsupported = true;
        return;
    }
    // Take every finished result, oldest first, without waiting for the others.
    for (unsigned int k = 0; k < RING; ++k)
    {
        const unsigned int i = (c.next + k) % RING;
        long long values[ATOMIC_COUNTERS] = {0, -1};
        if (!c.pending[i] || !collect(*ext, c, i, values)) continue;
        c.pending[i] = false;
        for (unsigned int n = 0; n < ATOMIC_COUNTERS; ++n) _last[n].store(values[n]);
    }
    if (c.pending[c.next]) return; // the GPU is far behind: skip this frame rather than wait
    if (atomic())
    {
        const GLuint zero[ATOMIC_COUNTERS] = {};
        ext->glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, c.ids[c.next]);
        ext->glBufferSubData(GL_ATOMIC_COUNTER_BUFFER, 0, sizeof(zero), zero);
        ext->glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, 0);
        ext->glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, ATOMIC_BINDING, c.ids[c.next]);
    }
    else
        ext->glBeginQuery(_target, c.ids[c.next]);
    c.active = true;
    _lastFrame.store(frameOf(info));
}

void GpuCounter::end(osg::RenderInfo& info)
{
    const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    PerContext& c = _contexts[info.getContextID()];
    if (!c.active) return;
    if (atomic())
    {
        ext->glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, ATOMIC_BINDING, 0);
        c.fences[c.next] = ext->glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    }
    else
        ext->glEndQuery(_target);
    c.active = false;
    c.pending[c.next] = true;
    c.next = (c.next + 1) % RING;
}

void GpuCounter::releaseGLObjects(osg::State* state) const
{
    // Query and buffer names die with their context; a context that lives on gets new ones.
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    if (state)
        _contexts.erase(state->getContextID());
    else
        _contexts.clear();
}

void GpuCounter::resizeGLObjectBuffers(unsigned int)
{
    // Per-context state lives in a map, which holds any context ID.
}

// ---------------------------------------------------------------------------------------
// BlockerQueries

BlockerQueries::BlockerQueries() : _geode(new osg::Geode)
{
    _geode->setName("osgShadowSilhouette blocker queries");
    _geode->setCullingActive(false);
    _geode->setDataVariance(osg::Object::DYNAMIC);
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE | osg::StateAttribute::PROTECTED;
    const auto off = osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE | osg::StateAttribute::PROTECTED;
    osg::StateSet* ss = _geode->getOrCreateStateSet();
    ss->setRenderBinDetails(100, "RenderBin"); // after every caster of the depth pass
    ss->setAttributeAndModes(new osg::Depth(osg::Depth::LEQUAL, 0.0, 1.0, false), on);
    ss->setMode(GL_POLYGON_OFFSET_FILL, off); // raw box depths against biased map depths: conservative
    ss->setMode(GL_DEPTH_CLAMP, on);          // box parts outside the depth range still count
    ss->setMode(GL_CULL_FACE, off);
}

BlockerQueries::~BlockerQueries() = default;

void BlockerQueries::update(const std::vector<Caster>& casters)
{
    static const GLuint boxIndices[36] = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                                          2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
    if (_boxes.size() != casters.size())
    {
        _geode->removeDrawables(0, _geode->getNumDrawables());
        _boxes.resize(casters.size());
        for (unsigned int i = 0; i < _boxes.size(); ++i)
        {
            if (!_boxes[i])
            {
                osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
                g->setUseDisplayList(false);
                g->setUseVertexBufferObjects(true);
                g->setDataVariance(osg::Object::DYNAMIC);
                g->setCullingActive(false);
                g->setVertexArray(new osg::Vec3Array(8));
                g->addPrimitiveSet(new osg::DrawElementsUInt(GL_TRIANGLES, 36, boxIndices));
                g->setDrawCallback(new IssueQueryCallback(this, i));
                _boxes[i] = g;
            }
            _geode->addDrawable(_boxes[i].get());
        }
    }
    for (std::size_t i = 0; i < casters.size(); ++i)
    {
        const osg::BoundingBox& local = casters[i].geometry->getBoundingBox();
        osg::Vec3Array& v = static_cast<osg::Vec3Array&>(*_boxes[i]->getVertexArray());
        bool changed = false;
        for (unsigned int k = 0; k < 8; ++k)
        {
            const osg::Vec3 corner = osg::Vec3(osg::Vec3d(local.corner(k)) * casters[i].world);
            changed |= v[k] != corner;
            v[k] = corner;
        }
        if (changed)
        {
            v.dirty();
            _boxes[i]->dirtyBound();
        }
    }
}

void BlockerQueries::issue(osg::RenderInfo& info, unsigned int index, const osg::Drawable* box)
{
    const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
    if (!queriesSupported(ext))
    {
        box->drawImplementation(info);
        return;
    }
    const unsigned int frame = frameOf(info);
    GLuint id = 0;
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
        PerContext& c = _contexts[info.getContextID()];
        if (c.collectedFrame != frame) // first query of a frame: count last frame's answers
        {
            c.collectedFrame = frame;
            unsigned int tested = 0, hidden = 0;
            for (std::size_t i = 0; i < c.ids.size(); ++i)
            {
                if (c.issuedFrame[i] == ~0u || c.issuedFrame[i] == frame) continue;
                GLuint available = 0, any = 1;
                ext->glGetQueryObjectuiv(c.ids[i], GL_QUERY_RESULT_AVAILABLE, &available);
                if (!available) continue;
                ext->glGetQueryObjectuiv(c.ids[i], GL_QUERY_RESULT, &any);
                ++tested;
                hidden += any == 0 ? 1 : 0;
            }
            _tested.store(tested);
            _hidden.store(hidden);
        }
        if (index >= c.ids.size())
        {
            const std::size_t old = c.ids.size();
            c.ids.resize(std::max<std::size_t>(index + 1, _boxes.size()), 0);
            c.issuedFrame.resize(c.ids.size(), ~0u);
            ext->glGenQueries(static_cast<GLsizei>(c.ids.size() - old), c.ids.data() + old);
        }
        id = c.ids[index];
        c.issuedFrame[index] = frame;
    }
    ext->glBeginQuery(GL_ANY_SAMPLES_PASSED, id);
    box->drawImplementation(info);
    ext->glEndQuery(GL_ANY_SAMPLES_PASSED);
}

GLuint BlockerQueries::issuedQuery(osg::RenderInfo& info, unsigned int index) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    auto it = _contexts.find(info.getContextID());
    if (it == _contexts.end() || index >= it->second.ids.size()) return 0;
    return it->second.issuedFrame[index] == frameOf(info) ? it->second.ids[index] : 0;
}

osg::ref_ptr<osg::Drawable::DrawCallback> BlockerQueries::createConditionalDraw(unsigned int index)
{
    return new ConditionalDrawCallback(this, index);
}

void BlockerQueries::releaseGLObjects(osg::State* state) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    if (state)
        _contexts.erase(state->getContextID());
    else
        _contexts.clear();
    _geode->releaseGLObjects(state); // the boxes and their state
}

void BlockerQueries::resizeGLObjectBuffers(unsigned int maxSize)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    _geode->resizeGLObjectBuffers(maxSize); // the query state itself lives in a map
}

// ---------------------------------------------------------------------------------------
// DrawnSamples

namespace {

class SamplesCallback : public osg::Camera::DrawCallback
{
public:
    SamplesCallback(DrawnSamples* samples, bool begin) : _samples(samples), _begin(begin) {}
    void operator()(osg::RenderInfo& info) const override
    {
        osg::ref_ptr<DrawnSamples> samples;
        if (!_samples.lock(samples)) return;
        if (_begin)
            samples->begin(info);
        else
            samples->end(info);
    }

private:
    osg::observer_ptr<DrawnSamples> _samples; // the pass owns both
    bool _begin;
};

class SamplesPollDrawable : public osg::Drawable
{
public:
    explicit SamplesPollDrawable(DrawnSamples* samples) : _samples(samples)
    {
        setUseDisplayList(false);
        setCullingActive(false);
        setDataVariance(osg::Object::DYNAMIC);
    }
    SamplesPollDrawable(const SamplesPollDrawable& d, const osg::CopyOp& op) : osg::Drawable(d, op), _samples(d._samples) {}
    osg::Object* cloneType() const override { return new SamplesPollDrawable(nullptr); }
    osg::Object* clone(const osg::CopyOp& op) const override { return new SamplesPollDrawable(*this, op); }
    const char* libraryName() const override { return "osgShadowSilhouette"; }
    const char* className() const override { return "DrawnSamplesPollDrawable"; }
    void drawImplementation(osg::RenderInfo& info) const override
    {
        osg::ref_ptr<DrawnSamples> samples;
        if (_samples.lock(samples)) samples->poll(info);
    }
    osg::BoundingBox computeBoundingBox() const override { return osg::BoundingBox(); } // see CallDrawable

private:
    osg::observer_ptr<DrawnSamples> _samples;
};

} // namespace

DrawnSamples::DrawnSamples()
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->setName("osgShadowSilhouette drawn-samples poll");
    geode->setCullingActive(false);
    geode->addDrawable(new SamplesPollDrawable(this));
    _pollNode = geode;
}

DrawnSamples::~DrawnSamples() = default;

osg::ref_ptr<osg::Camera::DrawCallback> DrawnSamples::createBegin()
{
    return new SamplesCallback(this, true);
}

osg::ref_ptr<osg::Camera::DrawCallback> DrawnSamples::createEnd()
{
    return new SamplesCallback(this, false);
}

void DrawnSamples::begin(osg::RenderInfo& info)
{
    const unsigned int build = ++_drawn;
    const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    PerContext& c = _contexts[info.getContextID()];
    if (c.unsupported || !_enabled) return;
    if (c.ids[0] == 0)
    {
        if (!queriesSupported(ext))
        {
            c.unsupported = true;
            return;
        }
        ext->glGenQueries(RING, c.ids);
    }
    // The slot after the newest pending query; full ring: this build stays unknown.
    unsigned int slot = c.next;
    while (c.builds[slot] != 0)
    {
        slot = (slot + 1) % RING;
        if (slot == c.next) return;
    }
    ext->glBeginQuery(GL_ANY_SAMPLES_PASSED, c.ids[slot]);
    c.builds[slot] = build;
    c.active = true;
}

void DrawnSamples::end(osg::RenderInfo& info)
{
    const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    PerContext& c = _contexts[info.getContextID()];
    if (!c.active) return;
    ext->glEndQuery(GL_ANY_SAMPLES_PASSED);
    c.active = false;
}

void DrawnSamples::poll(osg::RenderInfo& info)
{
    const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    auto it = _contexts.find(info.getContextID());
    if (it == _contexts.end() || it->second.active) return;
    PerContext& c = it->second;
    // Oldest first; queries finish in order.
    while (c.builds[c.next] != 0)
    {
        GLuint available = 0;
        ext->glGetQueryObjectuiv(c.ids[c.next], GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) return;
        GLuint64 value = 0;
        ext->glGetQueryObjectui64v(c.ids[c.next], GL_QUERY_RESULT, &value);
        _lastSamples = static_cast<long long>(value);
        _counted = c.builds[c.next];
        c.builds[c.next] = 0;
        c.next = (c.next + 1) % RING;
    }
}

void DrawnSamples::releaseGLObjects(osg::State* state) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    if (state)
        _contexts.erase(state->getContextID());
    else
        _contexts.clear();
}

void DrawnSamples::resizeGLObjectBuffers(unsigned int)
{
    // Per-context state lives in a map, which holds any context ID.
}

} // namespace osgShadowSilhouette
