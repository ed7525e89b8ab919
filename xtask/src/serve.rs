//! The live book served on 127.0.0.1 (`cargo xtask book --open`, and `cargo xtask
//! serve DIR` for the browser tests, which read the address from its first line): a
//! page that loads WebAssembly and workers needs a server, which must say what each
//! file is (a module worker is refused without a JavaScript type). Any static host
//! serves the book as well; this one serves the files of one folder, to this
//! machine only.

use std::io::{BufRead, BufReader, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Component, Path, PathBuf};

/// Serves `folder` until the command is stopped; with `open`, opens its first page
/// in the desktop's browser. The first line printed names the address.
pub fn serve(folder: &Path, open: bool) -> Result<(), String> {
    let listener = TcpListener::bind("127.0.0.1:0").map_err(|e| format!("cannot listen: {e}"))?;
    let port = listener.local_addr().map_err(|e| e.to_string())?.port();
    let address = format!("http://127.0.0.1:{port}/");
    println!("serving {} at {address} (Ctrl-C stops)", folder.display());
    std::io::stdout().flush().map_err(|e| e.to_string())?;
    if open {
        open_browser(&address);
    }
    for stream in listener.incoming().flatten() {
        if let Err(e) = answer(stream, folder) {
            eprintln!("{e}");
        }
    }
    Ok(())
}

/// Opens `address` in the desktop's browser, if there is one.
fn open_browser(address: &str) {
    let opener = if cfg!(target_os = "macos") {
        "open"
    } else if cfg!(windows) {
        "explorer"
    } else {
        "xdg-open"
    };
    let opened = std::process::Command::new(opener)
        .arg(address)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status();
    if !opened.is_ok_and(|status| status.success()) {
        println!("if no browser opened, open {address} in one");
    }
}

/// Answers one request: the file it names under `folder`, or 404. The request's
/// headers are read to their end first: a connection closed with bytes unread is
/// reset, and a browser may then lose the answer.
fn answer(mut stream: TcpStream, folder: &Path) -> Result<(), String> {
    let mut reader = BufReader::new(&stream);
    let mut request = String::new();
    reader.read_line(&mut request).map_err(|e| e.to_string())?;
    let mut header = String::new();
    while reader.read_line(&mut header).map_err(|e| e.to_string())? > 2 {
        header.clear();
    }
    let path = request.split_whitespace().nth(1).unwrap_or("/");
    let file = local_file(folder, path);
    let (status, kind, body) = match file.as_deref().map(std::fs::read) {
        Some(Ok(body)) => ("200 OK", content_type(file.as_deref()), body),
        _ => ("404 Not Found", "text/plain", b"not found".to_vec()),
    };
    let head = format!(
        "HTTP/1.1 {status}\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    );
    stream
        .write_all(head.as_bytes())
        .and_then(|()| stream.write_all(&body))
        .map_err(|e| e.to_string())
}

/// The file under `folder` that the request path `path` names (`index.html` for a
/// folder); `None` for a path that would leave the folder.
fn local_file(folder: &Path, path: &str) -> Option<PathBuf> {
    let path = path.split(['?', '#']).next().unwrap_or("");
    let relative = Path::new(path.trim_start_matches('/'));
    if relative
        .components()
        .any(|c| !matches!(c, Component::Normal(_)))
    {
        return None;
    }
    let file = folder.join(relative);
    Some(if file.is_dir() {
        file.join("index.html")
    } else {
        file
    })
}

/// The content type of `file`, by its extension.
fn content_type(file: Option<&Path>) -> &'static str {
    match file.and_then(Path::extension).and_then(|e| e.to_str()) {
        Some("html") => "text/html; charset=utf-8",
        Some("js" | "mjs") => "text/javascript",
        Some("css") => "text/css",
        Some("wasm") => "application/wasm",
        Some("svg") => "image/svg+xml",
        Some("png") => "image/png",
        Some("json") => "application/json",
        Some("woff2") => "font/woff2",
        _ => "application/octet-stream",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_stay_inside_the_folder() {
        let root = Path::new("/book");
        assert_eq!(
            local_file(root, "/live/demo.js?x=1"),
            Some(PathBuf::from("/book/live/demo.js"))
        );
        assert_eq!(local_file(root, "/../etc/passwd"), None);
        assert_eq!(
            local_file(root, "/live/./demo.js"),
            Some(PathBuf::from("/book/live/demo.js"))
        );
        assert_eq!(
            content_type(Some(Path::new("a/b.wasm"))),
            "application/wasm"
        );
        assert_eq!(
            content_type(Some(Path::new("worker.js"))),
            "text/javascript"
        );
    }
}
