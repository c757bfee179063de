//! Newmark integrator.
