#include "engine/integrator/estimate.h"

namespace mvpl::integrator {

sampler::SamplerSettings sampler_settings(const Estimate& e) {
    sampler::SamplerSettings s = e.sampling;
    s.width = int(e.render.width);
    s.height = int(e.render.height);
    s.clamp = e.render.clamp;
    s.vsl_radius = e.render.vsl_radius;
    s.specular_chains = e.render.chains;  // the Metropolis target follows them too
    return s;
}

reference::GatherOptions gather_options(const Estimate& e) {
    reference::GatherOptions g;
    g.width = int(e.render.width);
    g.height = int(e.render.height);
    g.clamp = e.render.clamp;
    g.vsl_radius = e.render.vsl_radius;
    g.max_depth = e.sampling.tracer.max_depth;
    g.subpixel = render::subpixel_schedule(e.render);
    g.chains = e.render.chains;
    g.chain_seed = e.render.chain_seed;
    g.interleave = int(e.render.interleave);
    return g;
}

CompensationOptions compensation_options(const Estimate& e) {
    CompensationOptions c;
    c.width = int(e.render.width);
    c.height = int(e.render.height);
    c.clamp = e.render.clamp;
    c.vsl_radius = e.render.vsl_radius;
    c.max_depth = e.sampling.tracer.max_depth;
    c.rr_depth = e.sampling.tracer.rr_depth;
    c.chains = e.render.chains;
    c.seed = e.sampling.seed;
    return c;
}

CausticOptions caustic_options(const Estimate& e) {
    CausticOptions k;
    k.width = int(e.render.width);
    k.height = int(e.render.height);
    k.max_depth = e.sampling.tracer.max_depth;
    k.rr_depth = e.sampling.tracer.rr_depth;
    k.specular = e.render.chains;
    k.clamp = e.compensate ? e.render.clamp : 0.0f;
    k.vsl_radius = e.render.vsl_radius;  // which share: lobe-wise or all
    k.seed = e.sampling.seed;
    return k;
}

manylights::RowColumnContext row_column_context(const Estimate& e) {
    manylights::RowColumnContext c;
    c.rows.width = int(e.render.width);
    c.rows.height = int(e.render.height);
    c.rows.chains = e.render.chains;
    c.clamp = e.render.clamp;
    c.vsl_radius = e.render.vsl_radius;
    c.seed = e.sampling.seed;
    return c;
}

}  // namespace mvpl::integrator
