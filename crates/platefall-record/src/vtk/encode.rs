//! The binary part of a VTK XML file: every array appended after the XML in one raw block
//! (`<AppendedData encoding="raw">`), each array zlib-compressed in blocks of [`BLOCK`] bytes
//! behind VTK's compression header (`header_type="UInt64"`: the number of blocks, the block
//! size, the size of a partial last block (0: the last block is full), then each block's
//! compressed size). The XML names each array by its byte offset in this block.
use std::fmt::Write as _;
use std::io::Write as _;

use flate2::write::ZlibEncoder;
use flate2::Compression;

/// Uncompressed bytes per compressed block (VTK's own default).
pub const BLOCK: usize = 1 << 15;

/// The element type of an array, as VTK names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scalar {
    /// `Float64`.
    F64,
    /// `Int64`.
    I64,
    /// `UInt8`.
    U8,
}

impl Scalar {
    /// VTK's name of the type.
    pub fn vtk_name(self) -> &'static str {
        match self {
            Scalar::F64 => "Float64",
            Scalar::I64 => "Int64",
            Scalar::U8 => "UInt8",
        }
    }
}

/// The arrays of one file: their XML tags (written as they are added) and their bytes.
#[derive(Debug, Default)]
pub struct Appended {
    data: Vec<u8>,
    raw: Vec<u8>,
}

impl Appended {
    /// Appends `values` (f64, little-endian) and returns the `<DataArray …/>` tag naming them.
    pub fn f64s(&mut self, name: &str, components: usize, values: &[f64]) -> String {
        self.raw.clear();
        self.raw.extend(values.iter().flat_map(|v| v.to_le_bytes()));
        self.push(
            name,
            Scalar::F64,
            components,
            values.len() / components.max(1),
        )
    }

    /// Appends `values` (i64, little-endian) and returns their tag.
    pub fn i64s(&mut self, name: &str, values: &[i64]) -> String {
        self.raw.clear();
        self.raw.extend(values.iter().flat_map(|v| v.to_le_bytes()));
        self.push(name, Scalar::I64, 1, values.len())
    }

    /// Appends `values` (bytes) and returns their tag.
    pub fn u8s(&mut self, name: &str, values: &[u8]) -> String {
        self.raw.clear();
        self.raw.extend_from_slice(values);
        self.push(name, Scalar::U8, 1, values.len())
    }

    /// The appended block: everything added so far.
    pub fn bytes(&self) -> &[u8] {
        &self.data
    }

    /// Compresses `self.raw` behind its header onto the block; the tag with its offset.
    fn push(&mut self, name: &str, kind: Scalar, components: usize, tuples: usize) -> String {
        let offset = self.data.len();
        let blocks: Vec<Vec<u8>> = self.raw.chunks(BLOCK).map(compress).collect();
        let last = (self.raw.len() % BLOCK) as u64;
        let header = [blocks.len() as u64, BLOCK as u64, last];
        let sizes = blocks.iter().map(|b| b.len() as u64);
        for word in header.into_iter().chain(sizes) {
            self.data.extend_from_slice(&word.to_le_bytes());
        }
        for b in &blocks {
            self.data.extend_from_slice(b);
        }
        let mut tag = format!("<DataArray type=\"{}\"", kind.vtk_name());
        if !name.is_empty() {
            let _ = write!(tag, " Name=\"{name}\"");
        }
        let _ = write!(
            tag,
            " NumberOfComponents=\"{components}\" NumberOfTuples=\"{tuples}\" \
             format=\"appended\" offset=\"{offset}\"/>"
        );
        tag
    }
}

/// One block, zlib-compressed at the fastest level (field data compress little more at higher
/// levels, and the logger has a snapshot to write every few hundred steps).
fn compress(block: &[u8]) -> Vec<u8> {
    let mut z = ZlibEncoder::new(Vec::with_capacity(block.len() / 2), Compression::fast());
    // Writing into a Vec cannot fail.
    let _ = z.write_all(block);
    z.finish().unwrap_or_default()
}

/// The start of every file: the XML declaration and the `VTKFile` element of `kind`.
pub fn file_head(kind: &str) -> String {
    format!(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"{kind}\" version=\"1.0\" \
         byte_order=\"LittleEndian\" header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n"
    )
}

/// The end of every file: the appended block and the closing tag, after the XML `text`.
pub fn file_bytes(text: &str, appended: &Appended) -> Vec<u8> {
    let mut out = Vec::with_capacity(text.len() + appended.bytes().len() + 64);
    out.extend_from_slice(text.as_bytes());
    out.extend_from_slice(b"  <AppendedData encoding=\"raw\">\n_");
    out.extend_from_slice(appended.bytes());
    out.extend_from_slice(b"\n  </AppendedData>\n</VTKFile>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Read as _;

    #[test]
    fn an_array_decodes_from_its_header_and_blocks() {
        let mut a = Appended::default();
        let _ = a.u8s("pad", &[7; 3]);
        let values: Vec<f64> = (0..10_000).map(|k| (k as f64).sin()).collect();
        let tag = a.f64s("x", 2, &values);
        assert!(tag.contains("NumberOfTuples=\"5000\""), "{tag}");
        let rest = tag.split("offset=\"").nth(1).unwrap();
        let offset: usize = rest.trim_end_matches("\"/>").parse().unwrap();
        let word = |k: usize| {
            let b = &a.bytes()[offset + 8 * k..offset + 8 * k + 8];
            u64::from_le_bytes(b.try_into().unwrap()) as usize
        };
        let (n, last) = (word(0), word(2));
        assert_eq!((n, word(1), last), (3, BLOCK, 80_000 - 2 * BLOCK));
        let mut at = offset + 8 * (3 + n);
        let mut raw = Vec::new();
        for k in 0..n {
            let c = word(3 + k);
            let mut z = flate2::read::ZlibDecoder::new(&a.bytes()[at..at + c]);
            z.read_to_end(&mut raw).unwrap();
            at += c;
        }
        let back: Vec<f64> = raw
            .chunks_exact(8)
            .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
            .collect();
        assert_eq!(back, values);
    }
}
