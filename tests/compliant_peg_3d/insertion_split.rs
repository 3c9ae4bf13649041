//! The insertion scene's peg and the pose of its run where a rim-on-mouth
//! minimum splits into two about a col (its gap profile flat to fourth
//! order there): shared by the flat-minimum and split-minimum tests.

use nalgebra::SVector;
use pegdyn::compliant_peg_3d::Peg3dParams;

/// The insertion scene's peg (`scenes/insert_rcc.toml`).
pub fn insertion_peg() -> Peg3dParams {
    let big_d = 0.025;
    Peg3dParams::steel(big_d * (1.0 - 0.003), 0.05, big_d, 3e-4, 5e-4, 0.03)
}

/// The pose `(p, q)` (unit quaternion) at the split met by the insertion
/// run (`scenes/insert_rcc.toml`), bit for bit.
pub fn split_pose() -> SVector<f64, 7> {
    let bits: [u64; 7] = [
        0xbf37b09fa5d0cf49,
        0x3be679acf269cbbe,
        0x3f98e23cbe72e960,
        0x3fefff9de5adef82,
        0xbc32ca770b5e651f,
        0xbf83cf23e2fb33f4,
        0xbbd132d1f73bb452,
    ];
    SVector::from(bits.map(f64::from_bits))
}
