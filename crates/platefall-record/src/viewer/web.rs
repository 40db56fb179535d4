//! The Rerun web viewer next to the `--serve` server (cargo feature `web`): its HTML, JavaScript
//! and wasm, built into the binary by the `re_web_viewer_server` crate, served over HTTP on the
//! server's bind address. The page connects to the server given in its `?url=`
//! ([`ServeOptions::web_url`]); no browser is ever started.
use crate::options::ServeOptions;

/// The HTTP server of the web viewer; it serves until dropped.
#[cfg(feature = "web")]
pub(crate) type WebServer = re_web_viewer_server::WebViewerServer;

/// The HTTP server of the web viewer (none can exist in a build without the `web` feature).
#[cfg(not(feature = "web"))]
pub(crate) enum WebServer {}

/// This build can serve the web viewer.
pub const WEB_AVAILABLE: bool = cfg!(feature = "web");

/// Starts the web viewer of `serve` (None without `web_port`); the error is one line naming
/// the option.
#[cfg(feature = "web")]
pub(crate) fn host_web_viewer(serve: &ServeOptions) -> anyhow::Result<Option<WebServer>> {
    let Some(port) = serve.web_port else {
        return Ok(None);
    };
    let config = rerun::web_viewer::WebViewerConfig {
        bind_ip: serve.bind.to_string(),
        web_port: port.into(),
        connect_to: vec![serve.url()],
        open_browser: false,
        ..Default::default()
    };
    let server = rerun::serve_web_viewer(config)
        .map_err(|e| anyhow::anyhow!("--bind {} --web-port {port}: {e}", serve.bind))?;
    Ok(Some(server))
}

/// Refuses a web viewer: this build has none.
#[cfg(not(feature = "web"))]
pub(crate) fn host_web_viewer(serve: &ServeOptions) -> anyhow::Result<Option<WebServer>> {
    match serve.web_port {
        Some(_) => anyhow::bail!("--web: this platefall was built without the `web` feature"),
        None => Ok(None),
    }
}
