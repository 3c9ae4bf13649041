//! The items of `src/scene/shared/sensitivities/mod.rs`: the names a
//! table may give, the rows a metric turns into and the rules that
//! withhold a derivative (the peak switching maximum, the seat near
//! `t_end`, the final depth near the target).

use pegdyn::scene::shared::sensitivities::{
    Measured, PARAMETERS_FIELD, choose, final_depth, peak_switch_flag, rows, seat_time,
};

const FIELDS: [&str; 3] = ["a.x", "a.y", "b.z"];

fn names(list: &[&str]) -> Vec<String> {
    list.iter().map(|s| (*s).to_owned()).collect()
}

#[test]
fn the_named_fields_come_in_the_order_named_and_bad_names_are_refused_with_the_valid_ones() {
    let (chosen, errors) = choose(&names(&["b.z", "a.x"]), &FIELDS);
    assert_eq!((chosen, errors.len()), (vec![2, 0], 0));
    let (chosen, errors) = choose(&names(&["a.y", "c.w", "a.y"]), &FIELDS);
    assert_eq!(chosen, vec![1]);
    let text: Vec<String> = errors.iter().map(ToString::to_string).collect();
    assert_eq!(text.len(), 2, "{text:?}");
    assert!(
        text[0].contains(PARAMETERS_FIELD)
            && text[0].contains("c.w")
            && text[0].contains("the fields are: a.x, a.y, b.z"),
        "{text:?}"
    );
    assert!(text[1].contains("named twice"), "{text:?}");
    let (chosen, errors) = choose(&[], &FIELDS);
    assert!(chosen.is_empty());
    assert!(errors[0].to_string().contains("name at least one field"));
}

#[test]
fn rows_give_the_elasticity_withhold_flagged_derivatives_and_flag_unused_and_non_finite_ones() {
    let values = [2.0, 0.5, 4.0];
    let metrics = [
        Measured {
            name: "m_s",
            value: Some(8.0),
            derivative: vec![3.0, f64::INFINITY, -1.0],
            flag: Box::new(|k| (k == 2).then(|| "a reason".to_owned())),
        },
        Measured {
            name: "zero_m",
            value: Some(0.0),
            derivative: vec![1.0, 1.0, 1.0],
            flag: Box::new(|_| None),
        },
    ];
    let unused = [false, false, true];
    let r = rows(&metrics, &[0, 1, 2], &unused, &values, &FIELDS);
    assert_eq!(r.len(), 6);
    // q/m dm/dq = 2/8 · 3
    assert_eq!((r[0].derivative, r[0].elasticity), (Some(3.0), Some(0.75)));
    assert!(r[0].flag.is_empty());
    // Infinite: flagged, never a number.
    assert_eq!((r[1].derivative, r[1].elasticity), (None, None));
    assert_eq!(r[1].flag, "the derivative is not finite at this point");
    // Unused wins over the metric's own flag: a zero, flagged.
    assert_eq!((r[2].derivative, r[2].elasticity), (Some(0.0), Some(0.0)));
    assert_eq!(r[2].flag, "not used by this model");
    // A derivative of −0 (a product with a zero factor) is written as 0.
    let signed = [Measured {
        name: "m_s",
        value: Some(8.0),
        derivative: vec![-0.0, 0.0, 0.0],
        flag: Box::new(|_| None),
    }];
    let z = rows(&signed, &[0], &[false; 3], &values, &FIELDS);
    assert_eq!(z[0].derivative.map(f64::to_bits), Some(0.0f64.to_bits()));
    assert_eq!(z[0].elasticity.map(f64::to_bits), Some(0.0f64.to_bits()));
    // A metric of value zero has derivatives but no elasticity.
    assert_eq!((r[3].derivative, r[3].elasticity), (Some(1.0), None));
    assert_eq!((r[3].metric, r[3].parameter), ("zero_m", "a.x"));
}

#[test]
fn a_peak_is_flagged_when_a_tenth_of_a_percent_change_may_reach_the_next_maximum() {
    // Field k moves the peak by 1e-3 · |q_k| · |dF/dq_k|: 1e-3 · 10 · 50
    // = 0.5 N for the first field, 0.005 N for the second.
    let flag = peak_switch_flag(
        " contact force".to_owned(),
        String::new(),
        (20.0, 19.2),
        vec![50.0, 0.5],
        vec![10.0, 10.0],
    );
    // Gap 0.8 N < 2 · 0.5 N: flagged, naming both maxima.
    let text = flag(0).expect("flagged");
    assert!(
        text.contains("switches to another force maximum")
            && text.contains("2.000000e1 N")
            && text.contains("1.920000e1 N"),
        "{text}"
    );
    assert_eq!(flag(1), None);
    // A tie is flagged whatever the derivative.
    let tie = peak_switch_flag(
        String::new(),
        String::new(),
        (5.0, 5.0),
        vec![0.0],
        vec![1.0],
    );
    assert!(tie(0).is_some());
}

#[test]
fn a_seat_near_t_end_and_a_final_depth_near_the_target_are_flagged_along_the_fields_that_reach_them()
 {
    // Seated at 0.99 s of 1 s: dt/dq = 20 s per unit moves the seat by
    // 1e-3 · 1 · 20 = 0.02 s, past t_end; dt/dq = 1 by 0.001 s, not.
    let m = seat_time(
        Some((0.99, vec![20.0, 1.0])),
        1.0,
        vec![1.0, 1.0],
        "unseated".to_owned(),
    );
    assert!((m.flag)(0).is_some_and(|t| t.contains("seated near t_end")));
    assert_eq!((m.flag)(1), None);
    let m = seat_time(
        None,
        1.0,
        vec![1.0, 1.0],
        "not seated (the run ended: x)".to_owned(),
    );
    assert_eq!(m.value, None);
    assert_eq!(
        (m.flag)(1).as_deref(),
        Some("not seated (the run ended: x)")
    );
    // Unseated 1e-5 m short of the target: a field moving the depth by
    // 1e-3 · 2 · 0.01 = 2e-5 m may seat it; a seated run is never flagged.
    let m = final_depth((0.00799, vec![0.01, 1e-4]), false, 0.008, vec![2.0, 2.0]);
    assert!((m.flag)(0).is_some_and(|t| t.contains("seats the peg")));
    assert_eq!((m.flag)(1), None);
    let m = final_depth((0.00799, vec![0.01, 1e-4]), true, 0.008, vec![2.0, 2.0]);
    assert_eq!((m.flag)(0), None);
}
