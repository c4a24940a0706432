// The four integrators of particles.hpp, written once over a 3-vector type with + and a product
// by its scalar type: Eigen's (the scalar reference, src/reference/particles/step-inl.hpp, in
// float and double) or a vector of lanes (simd/particles.cpp), so that both do the same
// operations in the same order. Included inside the includer's namespace (no include guard, by
// design: in a kernel file, inside the per-target namespace, so that it is compiled for the
// target), after core/particle_step.hpp.

// One step of length dt of x and v under the acceleration accel(x); `half` is 0.5 as a scalar.
template <class Vec, class Scalar, class Accel>
void integrateStep(std::uint32_t method, Vec& x, Vec& v, Scalar dt, Scalar half, Accel&& accel) {
  const Vec a = accel(x);
  switch (method) {
    case core::ParticleStepParams::kExplicitEuler:
      x = x + v * dt;
      v = v + a * dt;
      break;
    case core::ParticleStepParams::kSemiImplicitEuler:
      v = v + a * dt;
      x = x + v * dt;
      break;
    case core::ParticleStepParams::kVelocityVerlet: {
      x = x + v * dt + a * (half * dt * dt);
      const Vec a1 = accel(x);
      v = v + (a + a1) * (half * dt);
      break;
    }
    case core::ParticleStepParams::kPositionVerlet:
      x = x + v * dt + a * (dt * dt);
      v = v + a * dt;
      break;
  }
}
