//! Six-degree-of-freedom flight mechanics of a plate in three dimensions (docs/physics.md §9):
//! the centre's position and velocity in inertial axes, the orientation as a unit quaternion, the
//! angular velocity in body axes (x chord, y normal to the plate, z span; Y up, gravity −Y), with
//!
//! ```text
//!     m Ẍ₀ = F + (m − m_f) g_vec              (inertial axes, g_vec = (0, −g, 0))
//!     I ω̇ + ω × (I ω) = M                     (body axes, I the inertia tensor about the centre)
//!     q̇ = ½ q ⊗ (0, ω)
//! ```
//!
//! integrated with the variable-step Adams–Bashforth method of docs/physics.md §6 (orders 1–6, the
//! weights and history of [`super::AdamsBashforth`]), the orientation by the same weights in a
//! chart centred on the current orientation ([`RigidBody6`]); the strong coupling with the flow's
//! 6 × 6 added-mass matrix ([`StrongCoupling6`]); the plate's properties and the card of
//! Gallaway (1985) in three dimensions ([`Plate6`], [`PhysicalPlate6`]).
//!
//! Non-dimensional as in docs/physics.md §2 with the chord c as the only length: lengths by c,
//! velocities by U, time by c/U, mass by ρc³, inertia by ρc⁵, force by ρU²c², moment by ρU²c³,
//! g* = g c/U². A plate of span b has m* = m/(ρc³) = (b/c)·m/(ρc²b): the 2-D m* per unit span
//! times the span in chords (likewise I*).

mod card;
mod chart;
mod dynamics;
mod error;
mod plate;
mod rigid;
mod state;
mod strong;

pub use card::{box_inertia, thin_plate_inertia, PhysicalPlate6, Slab};
pub use dynamics::{explicit_acceleration, Accel6, Constraint6, Loads6};
pub use error::SixError;
pub use plate::Plate6;
pub use rigid::{RigidBody6, Snapshot6, SpinEntry};
pub use state::State6;
pub use strong::StrongCoupling6;
