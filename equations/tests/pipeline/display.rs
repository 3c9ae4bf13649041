//! Printing expressions: the paper's notation, and no node added by it.

use pegdyn_equations::Graph;

#[test]
fn prints_like_the_paper() {
    let g = Graph::new();
    let (x, y, a, b) = (g.var("x"), g.var("y"), g.param("a"), g.param("b"));
    let cases = [
        (-(a * b * x.sin()), "-a*b*sin(x)"),
        (a - b, "a - b"),
        (a / b, "a/b"),
        (a / (b * x), "a/(b*x)"),
        ((a + b) / x, "(a + b)/x"),
        (x.sqrt(), "sqrt(x)"),
        (x.powf(-0.5), "1/sqrt(x)"),
        (a / x.sqrt(), "a/sqrt(x)"),
        (x.powi(-2), "1/x^2"),
        ((a + b).square(), "(a + b)^2"),
        (-x.square(), "-x^2"),
        ((-x).powf(1.5), "(-x)^1.5"),
        (x.pow(-y), "x^(-y)"),
        (x.pow(a + b), "x^(a + b)"),
        (x / 2.0, "x/2"),
        (-x / 3.0, "-x/3"),
        (0.5 / x, "1/(2*x)"),
        (2.0 / x, "2/x"),
        (1.5 * x, "1.5*x"),
        (1e-20 * x, "1e-20*x"),
        (x - 3.0, "x - 3"),
        (x.sin().square(), "sin(x)^2"),
        ((x - y).max0(), "max0(x - y)"),
        (y.atan2(x), "atan2(y, x)"),
        ((-x).exp(), "exp(-x)"),
        (x * (a - b), "x*(a - b)"),
        (x.square().sqrt(), "abs(x)"),
        (g.constant(-2.5), "-2.5"),
    ];
    for (e, want) in cases {
        assert_eq!(e.to_string(), want);
    }
}

#[test]
fn printing_adds_no_nodes() {
    let g = Graph::new();
    let (x, y) = (g.var("x"), g.var("y"));
    let e = -3.0 * x * y / (x + y).sqrt() - x.powi(-3);
    let n = g.len();
    let _ = e.to_string();
    assert_eq!(g.len(), n);
}
