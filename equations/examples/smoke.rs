//! Prints a few expressions to show the simplifier and the infix display.
#![allow(clippy::eq_op)] // `x - x` and `x/x` are the point of the demo
use pegdyn_equations::Graph;
fn main() {
    let g = Graph::new();
    let th = g.var("theta");
    let w = g.var("thetadot");
    let (m, l, gr) = (g.param("m"), g.param("l"), g.param("g"));
    let t = 0.5 * m * (l * w).square();
    let v = -m * gr * l * th.cos();
    println!("L = {}", t - v);
    println!("x - x = {}", th - th);
    println!("x/x = {}", th / th);
    println!("x*x*2 + x^2 = {}", th * th * 2.0 + th.powi(2));
    println!("(a-b)/c = {}", (m - l) / gr);
    println!("(a+b)-(a+b) = {}", (m + l) - (m + l));
    println!("dL/dtheta = {}", (t - v).diff(th));
    println!("d/dt dL/dw = {}", (t - v).diff(w).dt(&[(th, w)]));
    println!("d sqrt(1-x^2) = {}", (1.0 - th.square()).sqrt().diff(th));
    println!(
        "sin^2+cos^2 = {}",
        m * th.sin().square() + m * th.cos().square() + l
    );
    println!("1-cos = {}", 1.0 - th.cos());
    println!("3m - 3m cos = {}", 3.0 * m - 3.0 * m * th.cos());
    println!("sin(-x) = {}, cos(-x) = {}", (-th).sin(), (-th).cos());
    println!("sin(l-m) + sin(m-l) = {}", (l - m).sin() + (m - l).sin());
    println!(
        "sqrt(x^2) = {}, sqrt(x^4) = {}",
        th.square().sqrt(),
        th.powi(4).sqrt()
    );
    println!(
        "a/(b*c) = {}, 1/sqrt(x) = {}, x^-2 = {}",
        m / (l * gr),
        th.powf(-0.5),
        th.powi(-2)
    );
    println!(
        "x^y = {}, (x+1)^(-y) = {}, 1e-20*x = {}",
        th.pow(m),
        (th + 1.0).pow(-m),
        1e-20 * th
    );
    println!(
        "-3 + x = {}, 2/x = {}, -x/3 = {}",
        th - 3.0,
        2.0 / th,
        -th / 3.0
    );
    println!(
        "hypot(-a, b) = {}, hypot(b,a) = {}",
        (-m).hypot(l),
        l.hypot(m)
    );
    println!("nodes {}", g.len());
}
