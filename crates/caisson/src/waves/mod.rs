//! Linear wave theory, breaking criteria and wave-height statistics (PHYSICS.md §3, §4.2).
