#include "gpu_model/model_terms.h"

namespace skinsim::gpu_model {

double shader_cycles(const sim::OpProfile& ops, const DeviceProfile& p) {
  // Instruction count x issue cycles per class, as an offline shader compiler reports
  // cycles (PVRShaderEditor); texture instructions take an issue slot (Imagination forum).
  // Mediump vector and scalar ops issue at alu.mediump_op_cost times the highp cost; no
  // source gives SGX a separate FP16 rate for transcendentals, so they cost the same.
  const double mediump = p.mediump_op_cost.value;
  const auto at_precision = [mediump](std::uint32_t all, std::uint32_t at_mediump) {
    return (all - at_mediump) + mediump * at_mediump;
  };
  return at_precision(ops.vector_ops, ops.vector_ops_mediump) * p.vector_op_cycles.value +
         at_precision(ops.scalar_ops, ops.scalar_ops_mediump) * p.scalar_op_cycles.value +
         ops.transcendental_ops * p.transcendental_op_cycles.value +
         ops.texture_reads() * p.texture_issue_cycles.value;
}

double cycles_per_ms(const DeviceProfile& p) {
  return p.clock_mhz.value * 1e3;
}

double dram_bytes_per_ms(const DeviceProfile& p) {
  // Peak GB/s x achievable fraction; 1 GB/s = 1e6 bytes per ms.
  return p.dram_peak_gb_per_s.value * p.dram_achievable_fraction.value * 1e6;
}

double pb_vertex_bytes(const DeviceProfile& p, double varying_floats) {
  // Position plus varyings, as the TA writes them to the parameter buffer.
  return p.pb_vertex_position_bytes.value + varying_floats * p.pb_bytes_per_varying_float.value;
}

}  // namespace skinsim::gpu_model
