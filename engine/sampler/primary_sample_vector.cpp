#include "engine/sampler/primary_sample_vector.h"

#include <cmath>
#include <numbers>

namespace mvpl::sampler {

float wrap_unit(double v) {
    const float w = float(v - std::floor(v));
    // v slightly below an integer gives w = 1 after rounding to float: that is 0 on the circle.
    return w < 1.0f ? w : 0.0f;
}

double standard_normal(Rng& rng) {
    // 1 − u ∈ (0, 1]: the logarithm is finite.
    const double u1 = 1.0 - double(rng.next_u32()) * 0x1p-32;
    const double u2 = double(rng.next_u32()) * 0x1p-32;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

PrimarySampleVector::PrimarySampleVector(uint64_t seed, uint64_t stream, float sigma)
    : m_rng(seed, stream), m_sigma(sigma) {}

void PrimarySampleVector::start_iteration(bool large_step) {
    ++m_iteration;
    m_large_step = large_step;
    m_dimension = 0;
}

void PrimarySampleVector::bring_up_to_date(Sample& x) {
    // A value older than the last accepted large step was replaced by it: draw it now.
    if (x.modified < m_last_large_step) {
        x.value = m_rng.next_float();
        x.modified = m_last_large_step;
    }
    x.value_backup = x.value;
    x.modified_backup = x.modified;
    if (m_large_step) {
        x.value = m_rng.next_float();
    } else {
        // The small steps this dimension missed, and this one, in one normal step.
        const int64_t steps = m_iteration - x.modified;
        const double s = double(m_sigma) * std::sqrt(double(steps));
        x.value = wrap_unit(double(x.value) + s * standard_normal(m_rng));
    }
    x.modified = m_iteration;
}

float PrimarySampleVector::next() {
    if (m_dimension >= m_x.size()) m_x.resize(m_dimension + 1);
    Sample& x = m_x[m_dimension++];
    // A dimension never read before (modified −1) is drawn as of the last large step and then
    // small-stepped since, as if it had been there all along.
    if (x.modified < m_iteration) bring_up_to_date(x);
    return x.value;
}

void PrimarySampleVector::accept() {
    if (m_large_step) m_last_large_step = m_iteration;
}

void PrimarySampleVector::reject() {
    for (Sample& x : m_x) {
        if (x.modified == m_iteration) {
            x.value = x.value_backup;
            x.modified = x.modified_backup;
        }
    }
    --m_iteration;
}

}  // namespace mvpl::sampler
