//! Field images as half-precision depth data.
use rerun::datatypes::ChannelDatatype;
use rerun::{DepthImage, RecordingStream, RecordingStreamResult};

use super::layout::FIELD_SCALES;
use platefall_post::ImageGrid;

/// Logs the three field images (vorticity, pressure, speed, laid out as `img`) under `base`,
/// each rounded to `levels` steps of its colour scale.
pub(super) fn log_field_images(
    rec: &RecordingStream,
    base: &str,
    images: [&[f32]; 3],
    img: &ImageGrid,
    levels: f64,
) -> RecordingStreamResult<()> {
    let size = [img.width as u32, img.height as u32];
    for (data, (name, _, lo, hi)) in images.into_iter().zip(FIELD_SCALES) {
        let quantum = ((hi - lo) / levels) as f32;
        rec.log(
            format!("{base}/{name}"),
            &DepthImage::from_data_type_and_bytes(
                f16_bytes(data, quantum),
                size,
                ChannelDatatype::F16,
            ),
        )?;
    }
    Ok(())
}

/// Half-precision little-endian bytes of `values`, rounded to multiples of `quantum` first (so
/// that the colour scale's resolution is kept and near-uniform regions become runs LZ4 can
/// compress). NaN (inside the plate) stays NaN.
pub(super) fn f16_bytes(values: &[f32], quantum: f32) -> Vec<u8> {
    let mut out = Vec::with_capacity(values.len() * 2);
    for &v in values {
        let q = if quantum > 0.0 && v.is_finite() {
            (v / quantum).round() * quantum
        } else {
            v
        };
        out.extend_from_slice(&half::f16::from_f32(q).to_le_bytes());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_are_quantised_then_stored_as_half_precision() {
        let bytes = f16_bytes(&[0.0, 1.0, -2.0, 0.3337, f32::NAN], 1.0 / 1024.0);
        let back: Vec<f32> = bytes
            .chunks(2)
            .map(|b| half::f16::from_le_bytes([b[0], b[1]]).to_f32())
            .collect();
        assert_eq!(&back[..3], &[0.0, 1.0, -2.0]);
        // 0.3337 rounds to 342/1024 = 0.333984375, which half precision holds exactly.
        assert_eq!(back[3], 342.0 / 1024.0);
        assert!(back[4].is_nan());
    }
}
