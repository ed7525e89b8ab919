//! Compiles tinybvh (`tiny_bvh/`, C++, header-only) and its C interface for the peers
//! benchmark, with the host's instructions (`-march=native`), as the Embree
//! benchmark is compiled.

fn main() {
    cc::Build::new()
        .cpp(true)
        .file("tiny_bvh/shim.cpp")
        .flag("-std=c++20")
        .flag("-march=native")
        .opt_level(3)
        .warnings(false)
        .compile("tinybvh");
    println!("cargo:rerun-if-changed=tiny_bvh");
}
