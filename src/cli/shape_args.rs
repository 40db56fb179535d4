//! The plate's section on the command line (`--shape`, `--thickness`, `--edge-radius`,
//! `--polygon`), turned into the library's [`Shape`].
use std::path::{Path, PathBuf};

use clap::Args;
use platefall_core::config::defaults;
use platefall_core::flow3d::Shape3;
use platefall_core::shape::{NacaCode, NotNaca, Shape};

use super::flags::ArgError;

/// The plate's section.
#[derive(Args, Debug, Clone)]
#[command(next_help_heading = "Plate section (exact: it does not change with --resolution)")]
pub struct ShapeArgs {
    /// The section: `rect` (sharp corners), `rounded` (corners rounded to --edge-radius),
    /// `ellipse` (axes c and --thickness), `circle` (diameter c), `nacaMPTT` (a NACA four-digit
    /// section of its own thickness, e.g. naca0012), or `polygon` (the vertices in --polygon).
    /// With --span, rect is the rectangular plate and ellipse and circle their cylinders along
    /// the span; three bodies need --span: `sphere` (diameter c, --span 1), `ellipsoid` (axes c,
    /// --thickness and the span) and `disk` (diameter c across the span, --thickness thick).
    #[arg(long, default_value = "rect", value_parser = parse_kind)]
    pub shape: ShapeKind,
    /// Plate thickness t/c, exact, in (0, 1] [default: 1/64 = 0.015625 for rect, rounded and
    /// ellipse, or the physical plate's t/c].
    #[arg(long, allow_negative_numbers = true)]
    pub thickness: Option<f64>,
    /// Edge radius r/c of a `rounded` plate, in (0, t/2] [default: t/2, round ends].
    #[arg(long, allow_negative_numbers = true)]
    pub edge_radius: Option<f64>,
    /// A text file of the `polygon`'s vertices in chords, one `x y` (or `x,y`) a line, the
    /// first vertex repeated at the end; `#` starts a comment.
    #[arg(long, value_name = "FILE")]
    pub polygon: Option<PathBuf>,
}

/// What `--shape` names.
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeKind {
    Rect,
    Rounded,
    Ellipse,
    Circle,
    Naca(NacaCode),
    Polygon,
    Sphere,
    Ellipsoid,
    Disk,
}

impl ShapeKind {
    /// The name `--shape` takes for the 3-D bodies (sphere, ellipsoid, disk); `section` for the
    /// rest.
    pub(crate) fn name(&self) -> &'static str {
        match self {
            ShapeKind::Sphere => "sphere",
            ShapeKind::Ellipsoid => "ellipsoid",
            ShapeKind::Disk => "disk",
            _ => "section",
        }
    }
}

/// A `--shape` value that names no section.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ShapeNameError {
    /// It starts with `naca` but is not a NACA four-digit code.
    #[error(transparent)]
    Naca(#[from] NotNaca),
    /// Any other unknown name.
    #[error(
        "`{0}` is not a shape: accepted rect, rounded, ellipse, circle, nacaMPTT (e.g. \
         naca0012), polygon, and with --span sphere, ellipsoid, disk"
    )]
    Unknown(String),
}

/// The section `--shape` names.
fn parse_kind(s: &str) -> Result<ShapeKind, ShapeNameError> {
    match s {
        "rect" => Ok(ShapeKind::Rect),
        "rounded" => Ok(ShapeKind::Rounded),
        "ellipse" => Ok(ShapeKind::Ellipse),
        "circle" => Ok(ShapeKind::Circle),
        "polygon" => Ok(ShapeKind::Polygon),
        "sphere" => Ok(ShapeKind::Sphere),
        "ellipsoid" => Ok(ShapeKind::Ellipsoid),
        "disk" => Ok(ShapeKind::Disk),
        other if other.to_ascii_lowercase().starts_with("naca") => {
            Ok(ShapeKind::Naca(NacaCode::parse(other)?))
        }
        other => Err(ShapeNameError::Unknown(other.to_string())),
    }
}

impl ShapeArgs {
    /// The section; `physical` is a physical plate's t/c, the thickness when none is given.
    pub(crate) fn shape(&self, physical: Option<f64>) -> Result<Shape, ArgError> {
        let t = self.thickness.or(physical).unwrap_or(defaults::THICKNESS);
        let refuse = |flag: &'static str, when: &'static str| ArgError::Refused { flag, when };
        if self.edge_radius.is_some() && self.shape != ShapeKind::Rounded {
            return Err(refuse("--edge-radius", "only goes with --shape rounded"));
        }
        if self.polygon.is_some() != (self.shape == ShapeKind::Polygon) {
            return Err(refuse(
                "--polygon",
                "goes with --shape polygon, and it needs one",
            ));
        }
        let own_thickness = matches!(
            self.shape,
            ShapeKind::Naca(_) | ShapeKind::Polygon | ShapeKind::Circle | ShapeKind::Sphere
        );
        if own_thickness && self.thickness.is_some() {
            return Err(refuse(
                "--thickness",
                "does not go with --shape circle, sphere, nacaMPTT or polygon (they have their own)",
            ));
        }
        let shape = match &self.shape {
            ShapeKind::Rect => Shape::Rect { thickness: t },
            ShapeKind::Rounded => Shape::Rounded {
                thickness: t,
                radius: self.edge_radius.unwrap_or(0.5 * t),
            },
            ShapeKind::Ellipse => Shape::Ellipse { thickness: t },
            ShapeKind::Circle | ShapeKind::Sphere => Shape::Ellipse { thickness: 1.0 },
            // The bodies' sections at mid-span.
            ShapeKind::Ellipsoid => Shape::Ellipse { thickness: t },
            ShapeKind::Disk => Shape::Rect { thickness: t },
            ShapeKind::Naca(code) => Shape::Naca { code: *code },
            ShapeKind::Polygon => Shape::Polygon {
                points: read_polygon(self.polygon.as_deref().unwrap_or(Path::new("")))?,
            },
        };
        shape.validate().map_err(|e| ArgError::Input(e.into()))?;
        Ok(shape)
    }
}

impl ShapeArgs {
    /// Whether the shape is a body of three dimensions only (it needs --span).
    pub(crate) fn needs_span(&self) -> bool {
        matches!(
            self.shape,
            ShapeKind::Sphere | ShapeKind::Ellipsoid | ShapeKind::Disk
        )
    }

    /// The body in the 3-D grid (docs/three-d.md "Bodies"), inscribed in the box of chord,
    /// thickness and span; None for the sections 3-D runs do not take.
    pub(crate) fn body3(&self) -> Option<Shape3> {
        match self.shape {
            ShapeKind::Rect => Some(Shape3::Box),
            ShapeKind::Ellipse | ShapeKind::Circle => Some(Shape3::SpanCylinder),
            ShapeKind::Sphere | ShapeKind::Ellipsoid => Some(Shape3::Ellipsoid),
            ShapeKind::Disk => Some(Shape3::Disk),
            ShapeKind::Rounded | ShapeKind::Naca(_) | ShapeKind::Polygon => None,
        }
    }
}

/// The vertices in a polygon file.
fn read_polygon(path: &Path) -> Result<Vec<[f64; 2]>, ArgError> {
    let bad = |why: String| ArgError::File {
        flag: "--polygon",
        path: path.display().to_string(),
        why,
    };
    let text = std::fs::read_to_string(path).map_err(|e| bad(e.to_string()))?;
    let mut points = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let nums: Vec<&str> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty())
            .collect();
        let parsed: Option<Vec<f64>> = nums.iter().map(|s| s.parse().ok()).collect();
        match parsed.as_deref() {
            Some([x, y]) => points.push([*x, *y]),
            _ => {
                return Err(bad(format!(
                    "line {} is `{line}`: accepted two numbers `x y` or `x,y`",
                    n + 1
                )))
            }
        }
    }
    Ok(points)
}
