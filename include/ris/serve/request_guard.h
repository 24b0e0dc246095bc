// Which requests `ris serve` obeys: the checks that keep a web page the user
// happens to visit from reading or driving the server (docs/serve.md, "Threat
// model"). Loopback alone is not a boundary: the user's browser is on the
// loopback, and it sends whatever any page asks it to.
//
// - Host: only the address the server listens on (a loopback server also
//   answers to localhost, 127.0.0.1 and [::1]), with its port; any other name
//   is a DNS-rebinding page's (evil.example resolving to 127.0.0.1), refused
//   on every route, GET included, so no such page reads the state.
// - Origin (or, absent, Referer): a request that changes state (any method
//   but GET, HEAD and OPTIONS) from a browser names the page that sent it; it
//   must be the server's own origin, http://<the Host asked for>. A GET under
//   /api/ with a foreign Origin, or that the browser marks as cross-site
//   (Sec-Fetch-Site), is refused too: an <img> on another site spends no CPU.
//   Clients that send neither header (curl, scripts) are not browsers and are
//   let through.
// - Content-Type: a state-changing request must say application/json (the
//   media type, exactly; parameters such as charset allowed). A browser sends
//   that type cross-origin only after a CORS preflight, which this server
//   never approves (it sends no CORS headers), so no form, no sendBeacon and
//   no "simple" fetch from another page can reach a state-changing route.
//   The one exception is the upload route (kUploadPath), whose body is a
//   file's bytes: it must say application/octet-stream, which is no more a
//   CORS-safelisted type than JSON is, so the same preflight rule holds.
//
// Example:
//   ris::RequestGuard guard("127.0.0.1", 8765);
//   ris::RequestGuard::Refusal r = guard.refusal({.method = "POST", .path = "/api/simulate",
//                                                 .host = "127.0.0.1:8765",
//                                                 .origin = "http://evil.example",
//                                                 .content_type = "text/plain"});
//   // r.status 403, r.message "cross-origin request refused: ..."
#pragma once

#include <set>
#include <string>

namespace ris {

// The headers the checks read; absent headers are empty.
struct RequestFacts {
  std::string method;
  std::string path;
  std::string host;
  std::string origin;
  std::string referer;
  std::string content_type;
  std::string sec_fetch_site;
};

class RequestGuard {
 public:
  // `listen_host` as given to --host ("127.0.0.1", "::1", "localhost", a name,
  // or a wildcard "0.0.0.0"/"::", which accepts the port on any IP literal:
  // an address cannot be rebound, only a name can).
  RequestGuard(const std::string& listen_host, int port);

  // status 0 when the request may proceed; otherwise the HTTP status (403 for
  // a foreign Host, Origin, Referer or Sec-Fetch-Site; 415 for a
  // state-changing request that is not JSON) and a sentence for the client.
  struct Refusal {
    int status = 0;
    std::string message;
  };
  Refusal refusal(const RequestFacts& request) const;

  bool host_allowed(const std::string& host) const;

 private:
  std::string expected_;         // the addresses, for messages
  std::set<std::string> hosts_;  // lower case names: "localhost", "127.0.0.1", "[::1]"
  bool any_ip_literal_ = false;
  int port_ = 0;
};

// True when `content_type`'s media type is application/json (case-insensitive,
// parameters after ';' ignored).
bool is_json_content_type(const std::string& content_type);

// The route that takes a file's bytes (POST /api/upload?kind=...&name=...).
inline constexpr const char* kUploadPath = "/api/upload";

// The media type a state-changing request to `path` must carry:
// application/octet-stream for kUploadPath, application/json elsewhere.
std::string required_content_type(const std::string& path);

// "scheme://authority" of a URL (lower case), or "" when it has none.
std::string origin_of_url(const std::string& url);

}  // namespace ris
