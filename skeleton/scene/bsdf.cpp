#include "scene/bsdf.h"

#include "core/sampling.h"

namespace pt {

Spectrum EmissionBSDF::sample_f(const Vec3&, Vec3* wi, double* pdf, Rng& rng) const {
  *wi = sample_cosine_hemisphere(rng.uniform2());
  *pdf = pdf_cosine_hemisphere(*wi);
  return Spectrum(0.0);
}

}  // namespace pt
