//! Rigid-body motion of the plate in Cartesian inertial form (docs/physics.md §6), non-dimensional (docs/physics.md §2).
//!
//! Inertial frame (docs/physics.md §3): X right, Y up, gravity −Y, θ counter-clockwise. The equations are
//! m* Ẍ = F_X, m* Ÿ = F_Y − m* g*, I* θ̈ = M, with (F_X, F_Y) in inertial axes, which stay regular
//! at V = 0 (unlike the dissertation's wind-axis form); V, γ, α are derived quantities.

use std::f64::consts::PI;

use super::adams::{AbError, AbHistory, AbStart, AdamsBashforth};
use crate::flow::Frame;

/// Non-dimensional plate properties (docs/physics.md §2): m* = m/(ρc²b), I* = I/(ρc⁴b), g* = g c/U², the
/// displaced fluid mass m_f* (buoyancy, docs/physics.md §2: the weight is g (ρs − ρf) t c per span) and an
/// applied moment.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PlateProps {
    /// m*, mass per unit span by ρc².
    pub mass: f64,
    /// I*, pitch inertia about the centre per unit span by ρc⁴.
    pub inertia: f64,
    /// g*, gravity by U²/c.
    pub gravity: f64,
    /// m_f*, the mass of the fluid the plate displaces by ρc² (t/c for a plate of thickness t);
    /// buoyancy m_f* g* acts upwards. 0 when the weight given is already the apparent weight.
    #[serde(default)]
    pub displaced: f64,
    /// An applied moment about the centre by ρU²c² (counter-clockwise), e.g. a motor on the pin.
    #[serde(default)]
    pub torque: f64,
}

impl PlateProps {
    /// Plate properties without buoyancy or applied moment.
    pub fn new(mass: f64, inertia: f64, gravity: f64) -> Self {
        Self {
            mass,
            inertia,
            gravity,
            displaced: 0.0,
            torque: 0.0,
        }
    }

    /// The downward acceleration the buoyancy-corrected weight alone gives the plate's own mass,
    /// g*(1 − m_f*/m*) (negative for a plate lighter than the fluid: it rises).
    pub fn apparent_gravity(&self) -> f64 {
        self.gravity * (1.0 - self.displaced / self.mass)
    }

    /// The buoyancy-corrected weight per span, (m* − m_f*) g*, by ρU²c (downwards).
    pub fn weight(&self) -> f64 {
        (self.mass - self.displaced) * self.gravity
    }
}

/// Rigid-body state in the inertial frame (docs/physics.md §3, §6): centre (X, Y), pitch θ and their rates.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct BodyState {
    /// X of the centre.
    pub x: f64,
    /// Y of the centre (up).
    pub y: f64,
    /// Pitch angle θ (counter-clockwise).
    pub theta: f64,
    /// Ẋ.
    pub xdot: f64,
    /// Ẏ.
    pub ydot: f64,
    /// θ̇.
    pub omega: f64,
}

/// Which degrees of freedom the body equations move (docs/physics.md §1, cases A–D).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Dof {
    /// Cases A, B: the caller imposes the motion; [`advance`] leaves the state untouched.
    Prescribed,
    /// Case C, pinned: θ free (I* θ̈ = M); translation at constant velocity (Ẍ = Ÿ = 0), no gravity.
    PitchOnly,
    /// Case D: X, Y, θ all free, with gravity.
    Free,
}

/// Fluid load per unit span on the plate (docs/physics.md §5): force (F_X, F_Y) in INERTIAL axes and moment M
/// about the centre (counter-clockwise positive), non-dimensional by ρU²c and ρU²c².
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct InertialLoads {
    /// F_X (inertial).
    pub fx: f64,
    /// F_Y (inertial).
    pub fy: f64,
    /// M about the centre.
    pub moment: f64,
}

impl InertialLoads {
    /// InertialLoads from a force given in BODY axes (x along the chord), rotated to inertial axes by θ
    /// (docs/physics.md §3: X = R(θ) x).
    pub fn from_body_axes(theta: f64, fx_body: f64, fy_body: f64, moment: f64) -> Self {
        let (fx, fy) = body_to_inertial(theta, fx_body, fy_body);
        Self { fx, fy, moment }
    }
}

/// Rotate a body-axes vector (x along the chord) to inertial axes: R(θ)(a, b) (docs/physics.md §3).
pub fn body_to_inertial(theta: f64, a: f64, b: f64) -> (f64, f64) {
    let (s, c) = theta.sin_cos();
    (c * a - s * b, s * a + c * b)
}

/// Rotate an inertial vector to body axes: Rᵀ(θ)(A, B) (docs/physics.md §3, u = Rᵀ U).
pub fn inertial_to_body(theta: f64, a: f64, b: f64) -> (f64, f64) {
    let (s, c) = theta.sin_cos();
    (c * a + s * b, -s * a + c * b)
}

/// Wrap an angle into (−π, π].
pub fn wrap_angle(a: f64) -> f64 {
    let r = a.rem_euclid(2.0 * PI); // [0, 2π]
    if r > PI {
        r - 2.0 * PI
    } else {
        r
    }
}

impl BodyState {
    /// The state as the integrator's vector (X, Y, θ, Ẋ, Ẏ, θ̇).
    pub fn to_array(&self) -> [f64; 6] {
        [self.x, self.y, self.theta, self.xdot, self.ydot, self.omega]
    }

    /// The state from the integrator's vector (X, Y, θ, Ẋ, Ẏ, θ̇).
    pub fn from_array(v: [f64; 6]) -> Self {
        let [x, y, theta, xdot, ydot, omega] = v;
        Self {
            x,
            y,
            theta,
            xdot,
            ydot,
            omega,
        }
    }

    /// Speed V = |(Ẋ, Ẏ)| (docs/physics.md §6).
    pub fn speed(&self) -> f64 {
        self.xdot.hypot(self.ydot)
    }

    /// Flight-path angle γ = atan2(Ẏ, Ẋ) ∈ [−π, π] (docs/physics.md §3, §6); 0 when V = 0.
    pub fn flight_path_angle(&self) -> f64 {
        self.ydot.atan2(self.xdot)
    }

    /// Angle of attack α = θ − γ wrapped into (−π, π] (docs/physics.md §5, §6).
    pub fn angle_of_attack(&self) -> f64 {
        wrap_angle(self.theta - self.flight_path_angle())
    }

    /// The motion as the flow solver sees it (docs/physics.md §3): the centre's velocity along the body axes,
    /// (ẋ₀cosθ + ẏ₀sinθ, −ẋ₀sinθ + ẏ₀cosθ) = (V cos α, −V sin α), and θ̇.
    pub fn frame(&self) -> Frame {
        let (u0, v0) = inertial_to_body(self.theta, self.xdot, self.ydot);
        Frame {
            u0,
            v0,
            omega: self.omega,
        }
    }
}

/// Time derivative of (X, Y, θ, Ẋ, Ẏ, θ̇) under the Cartesian equations of docs/physics.md §6 with the loads
/// taken as given (explicit coupling), T the applied moment and g*(1 − m_f*/m*) the buoyancy-
/// corrected gravity: `Free`: (Ẋ, Ẏ, θ̇, F_X/m*, F_Y/m* − g*(1 − m_f*/m*), (M + T)/I*);
/// `PitchOnly`: (Ẋ, Ẏ, θ̇, 0, 0, (M + T)/I*); `Prescribed`: (Ẋ, Ẏ, θ̇, 0, 0, 0) (constant velocity;
/// the real prescribed motion is the caller's).
pub fn state_derivative(
    props: &PlateProps,
    dof: Dof,
    s: &BodyState,
    loads: &InertialLoads,
) -> [f64; 6] {
    let pitch = (loads.moment + props.torque) / props.inertia;
    let (ax, ay, alpha) = match dof {
        Dof::Prescribed => (0.0, 0.0, 0.0),
        Dof::PitchOnly => (0.0, 0.0, pitch),
        Dof::Free => (
            loads.fx / props.mass,
            loads.fy / props.mass - props.apparent_gravity(),
            pitch,
        ),
    };
    [s.xdot, s.ydot, s.omega, ax, ay, alpha]
}

/// One explicit coupling step t → t + h of the body (docs/physics.md §6 coupling): with the loads of the
/// current flow, the derivative of [`state_derivative`] goes to the Adams–Bashforth integrator,
/// which advances `state`. For `Dof::Prescribed` nothing happens (the integrator is not fed).
pub fn advance(
    ab: &mut AdamsBashforth<6>,
    props: &PlateProps,
    dof: Dof,
    t: f64,
    state: &mut BodyState,
    loads: &InertialLoads,
    h: f64,
) {
    if dof == Dof::Prescribed {
        return;
    }
    let f = state_derivative(props, dof, state, loads);
    let mut y = state.to_array();
    ab.step(t, &mut y, f, h);
    *state = BodyState::from_array(y);
}

/// The plate as a rigid body: properties, free degrees of freedom, state and its integrator.
#[derive(Debug, Clone)]
pub struct RigidBody {
    /// Non-dimensional properties.
    pub props: PlateProps,
    /// Current state.
    pub state: BodyState,
    dof: Dof,
    ab: AdamsBashforth<6>,
}

impl RigidBody {
    /// A body with the given properties, freedom, initial state and AB order/start (docs/physics.md §6).
    ///
    /// # Errors
    /// [`AbError::Order`] when `order` is outside 1..=6.
    pub fn new(
        props: PlateProps,
        dof: Dof,
        state: BodyState,
        order: usize,
        start: AbStart,
    ) -> Result<Self, AbError> {
        Ok(Self {
            props,
            state,
            dof,
            ab: AdamsBashforth::new(order, start)?,
        })
    }

    /// Current degrees of freedom.
    pub fn dof(&self) -> Dof {
        self.dof
    }

    /// Change the degrees of freedom (release) and reset the derivative history, which belonged
    /// to the previous equations of motion.
    pub fn set_dof(&mut self, dof: Dof) {
        self.dof = dof;
        self.ab.reset();
    }

    /// The integrator (e.g. to inspect its history).
    pub fn integrator(&self) -> &AdamsBashforth<6> {
        &self.ab
    }

    /// The integrator, mutably (e.g. to prime its history).
    pub fn integrator_mut(&mut self) -> &mut AdamsBashforth<6> {
        &mut self.ab
    }

    /// Derivative of the current state under `loads` ([`state_derivative`]).
    pub fn derivative(&self, loads: &InertialLoads) -> [f64; 6] {
        state_derivative(&self.props, self.dof, &self.state, loads)
    }

    /// Advance t → t + h under the current loads ([`advance`]).
    pub fn step(&mut self, t: f64, loads: &InertialLoads, h: f64) {
        advance(
            &mut self.ab,
            &self.props,
            self.dof,
            t,
            &mut self.state,
            loads,
            h,
        );
    }

    /// Advance t → t + h with a derivative of (X, Y, θ, Ẋ, Ẏ, θ̇) the caller computed (strong
    /// coupling: [`StrongCoupling::derivative`](super::strong::StrongCoupling::derivative)).
    /// Nothing happens for `Dof::Prescribed`.
    pub fn step_with(&mut self, t: f64, f: [f64; 6], h: f64) {
        if self.dof == Dof::Prescribed {
            return;
        }
        let mut y = self.state.to_array();
        self.ab.step(t, &mut y, f, h);
        self.state = BodyState::from_array(y);
    }

    /// The body's changing part, for a checkpoint: state, freedom and derivative history.
    pub fn save(&self) -> BodySnapshot {
        BodySnapshot {
            state: self.state,
            dof: self.dof,
            history: self.ab.save_history(),
        }
    }

    /// Puts back what [`save`](Self::save) returned (the properties stay this body's own).
    ///
    /// # Errors
    /// [`AbError::HistoryShape`] when the saved history does not fit; the body is then unchanged.
    pub fn restore(&mut self, snap: &BodySnapshot) -> Result<(), AbError> {
        self.ab.restore_history(&snap.history)?;
        self.state = snap.state;
        self.dof = snap.dof;
        Ok(())
    }
}

/// A [`RigidBody`]'s changing part as plain data (a checkpoint's).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BodySnapshot {
    /// The state.
    pub state: BodyState,
    /// The free degrees of freedom.
    pub dof: Dof,
    /// The integrator's stored derivatives.
    pub history: AbHistory,
}
