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
    println!("dL/dtheta = {}", (t - v).diff(th));
    println!("d/dt dL/dw = {}", (t - v).diff(w).dt(&[(th, w)]));
    println!("d sqrt(1-x^2) = {}", (1.0 - th.square()).sqrt().diff(th));
    println!("nodes {}", g.len());
}
#[allow(dead_code)]
fn _unused() {}
