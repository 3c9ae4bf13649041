//! The items of `src/compliant_peg_3d/contact.rs`.

use pegdyn::compliant_peg_3d::contact::Pair;

#[test]
fn a_pairs_index_is_its_place_in_all() {
    for (k, p) in Pair::ALL.iter().enumerate() {
        assert_eq!(p.index(), k);
    }
}
