//! `cargo xtask book [--open]`: the live book, in English and in French. The crate
//! compiled to WebAssembly (the `web` package), its JavaScript bindings made by
//! wasm-bindgen into `book/src/live/pkg/`, then the book built by mdBook into
//! `book/build/`, and its French translation (`book/po/fr.po`) into
//! `book/build/fr/`; with `--open`, served on 127.0.0.1 and opened in a browser.
//! What is missing is installed first, at the versions CI uses.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The WebAssembly target.
const TARGET: &str = "wasm32-unknown-unknown";
/// WebAssembly's 128-bit SIMD, which the fast engine's portable lanes use (two
/// `f64` or four `f32` to an instruction); every browser the book supports runs it.
const SIMD: &str = "-C target-feature=+simd128";
/// A tool the book is built with, which cargo installs from crates.io.
struct Tool<'a> {
    /// The command it installs.
    command: &'a str,
    /// Its package.
    package: &'a str,
    /// The version the book is built with.
    version: &'a str,
    /// The features the book needs (`Some("")`: none), `None` for the package's own
    /// defaults: fewer features compile fewer crates (mdBook without its server and
    /// its watcher, which `cargo xtask book --open` does not use; wasm-bindgen
    /// without TLS, as it downloads nothing).
    features: Option<&'a str>,
}

/// mdBook, its formula preprocessor and its translation tools, at the versions the
/// book is built with.
const MDBOOK: [Tool; 3] = [
    Tool {
        command: "mdbook",
        package: "mdbook",
        version: "0.5.4",
        features: Some("search"),
    },
    Tool {
        command: "mdbook-katex",
        package: "mdbook-katex",
        version: "0.10.0",
        features: None,
    },
    Tool {
        command: "mdbook-xgettext",
        package: "mdbook-i18n-helpers",
        version: "0.4.0",
        features: None,
    },
];

/// How the tools are compiled, as cargo's settings for the release profile: without
/// link-time optimisation (mdbook-katex asks for it, and it is most of its link)
/// and at optimisation level 1, which compiles in less time than 3 and still builds
/// both books in seconds.
const TOOL_PROFILE: [(&str, &str); 2] = [
    ("CARGO_PROFILE_RELEASE_LTO", "false"),
    ("CARGO_PROFILE_RELEASE_OPT_LEVEL", "1"),
];

/// The book's translations, each with its title: `book/po/LANG.po`, built into
/// `book/build/LANG/`.
const LANGUAGES: [(&str, &str); 1] = [("fr", "raycourse : le lancer de rayons en sept séances")];

/// Installs mdBook, its formula preprocessor and its translation tools where they are
/// missing, at the versions the book is built with ([`MDBOOK`]), all compiled in
/// one target folder, `target/book-tools`, so that the crates they share compile
/// once.
pub fn install_tools(root: &Path) -> Result<(), String> {
    MDBOOK
        .iter()
        .try_for_each(|tool| install_if_missing(root, tool))
}

/// Builds the live book; with `open`, serves it and opens it.
pub fn build(root: &Path, open: bool) -> Result<(), String> {
    let wasm = compile(root)?;
    bindings(root, &wasm)?;
    install_tools(root)?;
    let html = root.join("book/build");
    run(Command::new("mdbook").arg("build").arg(root.join("book")))?;
    for (language, title) in LANGUAGES {
        run(Command::new("mdbook")
            .arg("build")
            .arg(root.join("book"))
            .arg("--dest-dir")
            .arg(html.join(language))
            .env("MDBOOK_BOOK__LANGUAGE", language)
            .env("MDBOOK_BOOK__TITLE", title))?;
    }
    println!("the live book -> {} (French: fr/)", html.display());
    if open {
        crate::serve::serve(&html, true)?;
    }
    Ok(())
}

/// Compiles the `web` package for the browser and returns the module's path. The
/// standard route is rustup's target; where rustup cannot fetch it, Debian's
/// `rustc-web` builds the standard library from source (`rust-web-src`) and links
/// with `wasm-ld-19`.
fn compile(root: &Path) -> Result<PathBuf, String> {
    let target_dir = root.join("target/wasm");
    let mut cargo = if rustup_has_target() {
        let mut cargo = Command::new("cargo");
        cargo.env("RUSTFLAGS", SIMD);
        cargo
    } else {
        println!(
            "rustup has no {TARGET} target here: building with Debian's rustc-web, \
             the standard library from source"
        );
        debian_cargo()?
    };
    cargo
        .current_dir(root)
        .args(["build", "--release", "--package", "raycourse-web", "--lib"])
        .args(["--target", TARGET])
        .env("CARGO_TARGET_DIR", &target_dir);
    run(&mut cargo)?;
    Ok(target_dir.join(TARGET).join("release/raycourse_web.wasm"))
}

/// Whether rustup has the WebAssembly target, adding it if it can.
fn rustup_has_target() -> bool {
    let installed =
        |out: std::process::Output| String::from_utf8_lossy(&out.stdout).contains(TARGET);
    let listed = Command::new("rustup")
        .args(["target", "list", "--installed"])
        .output();
    if listed.is_ok_and(installed) {
        return true;
    }
    println!("adding the {TARGET} target with rustup (half a minute at most)");
    let add = ["rustup", "target", "add", TARGET];
    let added = match Command::new("timeout").arg("30").args(add).status() {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            Command::new(add[0]).args(&add[1..]).status()
        }
        other => other,
    };
    added.is_ok_and(|s| s.success())
}

/// Debian's cargo and rustc-web, set to build the standard library for the target.
fn debian_cargo() -> Result<Command, String> {
    let needed = [
        ("/usr/bin/rustc", "rustc-web"),
        ("/usr/lib/rustlib/src/rust/library", "rust-web-src"),
        ("/usr/bin/wasm-ld-19", "lld-19"),
        ("/usr/bin/cargo", "cargo-web"),
    ];
    let missing: Vec<&str> = needed
        .iter()
        .filter(|(path, _)| !Path::new(path).exists())
        .map(|(_, package)| *package)
        .collect();
    if !missing.is_empty() {
        return Err(format!(
            "neither rustup's {TARGET} target nor Debian's rustc-web is here: \
             `rustup target add {TARGET}`, or `apt-get install {}`",
            missing.join(" ")
        ));
    }
    let mut cargo = Command::new("/usr/bin/cargo");
    cargo
        .arg("-Zbuild-std=std,panic_abort")
        .env("RUSTC", "/usr/bin/rustc")
        .env("RUSTC_BOOTSTRAP", "1")
        .env("RUSTFLAGS", format!("-C linker=wasm-ld-19 {SIMD}"))
        .env_remove("RUSTUP_TOOLCHAIN")
        .env_remove("CARGO");
    Ok(cargo)
}

/// The JavaScript bindings of `wasm`, with the module, in `book/src/live/pkg/`, by
/// the wasm-bindgen that `web/Cargo.toml` pins.
fn bindings(root: &Path, wasm: &Path) -> Result<(), String> {
    let version = pinned_wasm_bindgen(root)?;
    let tool = Tool {
        command: "wasm-bindgen",
        package: "wasm-bindgen-cli",
        version: &version,
        features: Some(""),
    };
    install_if_missing(root, &tool)?;
    run(Command::new("wasm-bindgen")
        .args(["--target", "web", "--no-typescript", "--out-dir"])
        .arg(root.join("book/src/live/pkg"))
        .arg(wasm))
}

/// The version of wasm-bindgen in `web/Cargo.toml` (`wasm-bindgen = "=X.Y.Z"`).
fn pinned_wasm_bindgen(root: &Path) -> Result<String, String> {
    let manifest = std::fs::read_to_string(root.join("web/Cargo.toml"))
        .map_err(|e| format!("web/Cargo.toml: {e}"))?;
    pinned_in(&manifest).ok_or_else(|| {
        "web/Cargo.toml: no `wasm-bindgen = \"=X.Y.Z\"` among the dependencies".into()
    })
}

/// The version that the manifest `text` pins wasm-bindgen to, `=X.Y.Z`, read as
/// TOML: a plain string or a table's `version`.
fn pinned_in(text: &str) -> Option<String> {
    let doc: toml_edit::DocumentMut = text.parse().ok()?;
    let dependency = doc.get("dependencies")?.get("wasm-bindgen")?;
    let version = dependency
        .as_str()
        .or_else(|| dependency.get("version")?.as_str())?;
    version.strip_prefix('=').map(str::to_owned)
}

/// Installs `tool` with cargo unless its command's `--version` names its version
/// (or, for a tool without `--version`, cargo lists it as installed).
fn install_if_missing(root: &Path, tool: &Tool) -> Result<(), String> {
    let found = Command::new(tool.command).arg("--version").output();
    if found.is_ok_and(|out| String::from_utf8_lossy(&out.stdout).contains(tool.version)) {
        return Ok(());
    }
    let listed = Command::new("cargo").args(["install", "--list"]).output();
    let wanted = format!("{} v{}:", tool.package, tool.version);
    if listed.is_ok_and(|out| String::from_utf8_lossy(&out.stdout).contains(&wanted)) {
        return Ok(());
    }
    println!(
        "installing {} {} (once; a few minutes)",
        tool.package, tool.version
    );
    let mut cargo = Command::new("cargo");
    cargo
        .args(["install", tool.package, "--version", tool.version])
        .arg("--target-dir")
        .arg(root.join("target/book-tools"))
        .envs(TOOL_PROFILE);
    if let Some(features) = tool.features {
        cargo.args(["--no-default-features", "--features", features]);
    }
    run(&mut cargo)
}

/// Runs `command`, an error naming it if it fails.
fn run(command: &mut Command) -> Result<(), String> {
    let status = command.status().map_err(|e| format!("{command:?}: {e}"))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("{command:?} failed ({status})"))
    }
}

#[cfg(test)]
mod tests {
    use super::pinned_in;

    #[test]
    fn the_pinned_wasm_bindgen_is_read_from_the_manifest_whatever_its_form() {
        let plain = "[package]\nname = \"web\"\n\n[dependencies]\nwasm-bindgen = \"=0.2.130\"\n";
        assert_eq!(pinned_in(plain).as_deref(), Some("0.2.130"));
        let table =
            "[dependencies]\nwasm-bindgen = { version = \"=0.2.1\", default-features = false }\n";
        assert_eq!(pinned_in(table).as_deref(), Some("0.2.1"));
        assert_eq!(pinned_in("[dependencies]\nwasm-bindgen = \"0.2\"\n"), None);
        assert_eq!(
            pinned_in("[dev-dependencies]\nwasm-bindgen = \"=0.2.130\"\n"),
            None
        );
    }
}
