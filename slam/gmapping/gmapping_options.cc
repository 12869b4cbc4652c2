#include "slam/gmapping/gmapping_options.h"

#include "evaluator/core/input_error.h"

namespace slamsweep::slam::gmapping {
namespace {

void RequirePositive(double value, const char* name) {
  if (!(value > 0.0)) throw evaluator::InputError(std::string("parameter ") + name + ": expected a value > 0");
}

}  // namespace

GmappingOptions ReadGmappingOptions(Parameters& parameters, const evaluator::LaserScan& first_scan) {
  GmappingOptions o;
  o.maxRange = parameters.Real("maxRange", first_scan.range_max_m - 0.01);
  o.maxUrange = parameters.Real("maxUrange", o.maxRange);
  o.sigma = parameters.Real("sigma", o.sigma);
  o.kernelSize = parameters.Integer("kernelSize", o.kernelSize);
  o.lstep = parameters.Real("lstep", o.lstep);
  o.astep = parameters.Real("astep", o.astep);
  o.iterations = parameters.Integer("iterations", o.iterations);
  o.lsigma = parameters.Real("lsigma", o.lsigma);
  o.ogain = parameters.Real("ogain", o.ogain);
  o.lskip = parameters.Integer("lskip", o.lskip);
  o.minimumScore = parameters.Real("minimumScore", o.minimumScore);
  o.srr = parameters.Real("srr", o.srr);
  o.srt = parameters.Real("srt", o.srt);
  o.str = parameters.Real("str", o.str);
  o.stt = parameters.Real("stt", o.stt);
  o.linearUpdate = parameters.Real("linearUpdate", o.linearUpdate);
  o.angularUpdate = parameters.Real("angularUpdate", o.angularUpdate);
  o.temporalUpdate = parameters.Real("temporalUpdate", o.temporalUpdate);
  o.resampleThreshold = parameters.Real("resampleThreshold", o.resampleThreshold);
  o.particles = parameters.Integer("particles", o.particles);
  o.xmin = parameters.Real("xmin", o.xmin);
  o.ymin = parameters.Real("ymin", o.ymin);
  o.xmax = parameters.Real("xmax", o.xmax);
  o.ymax = parameters.Real("ymax", o.ymax);
  o.delta = parameters.Real("delta", o.delta);
  o.llsamplerange = parameters.Real("llsamplerange", o.llsamplerange);
  o.llsamplestep = parameters.Real("llsamplestep", o.llsamplestep);
  o.lasamplerange = parameters.Real("lasamplerange", o.lasamplerange);
  o.lasamplestep = parameters.Real("lasamplestep", o.lasamplestep);
  RequirePositive(o.maxRange, "maxRange");
  RequirePositive(o.maxUrange, "maxUrange");
  RequirePositive(o.delta, "delta");
  if (o.particles < 1) throw evaluator::InputError("parameter particles: expected at least 1");
  if (o.kernelSize < 0 || o.iterations < 0 || o.lskip < 0) {
    throw evaluator::InputError("parameters kernelSize, iterations, lskip: expected values >= 0");
  }
  if (!(o.xmin < o.xmax && o.ymin < o.ymax))
    throw evaluator::InputError("parameters xmin/xmax, ymin/ymax: expected min < max");
  return o;
}

}  // namespace slamsweep::slam::gmapping
