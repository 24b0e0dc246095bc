#include "ris/serve/request_guard.h"

#include <arpa/inet.h>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>

namespace ris {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool is_ip_literal(const std::string& name) {
  unsigned char buf[16];
  if (name.size() > 2 && name.front() == '[' && name.back() == ']') {
    return inet_pton(AF_INET6, name.substr(1, name.size() - 2).c_str(), buf) == 1;
  }
  return inet_pton(AF_INET, name.c_str(), buf) == 1;
}

// "name:port" or "[v6]:port" (or no port: 80, the browser's default) into
// its name and port; false for anything else.
bool split_host(const std::string& host, std::string& name, int& port) {
  const std::size_t close = host.rfind(']');
  const std::size_t colon = host.rfind(':');
  const bool has_port = colon != std::string::npos && (close == std::string::npos || colon > close);
  name = has_port ? host.substr(0, colon) : host;
  port = 80;
  if (has_port) {
    const std::string digits = host.substr(colon + 1);
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), port);
    if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size()) return false;
  }
  return !name.empty();
}

bool is_api(const std::string& path) {
  return path.rfind("/api/", 0) == 0;
}

bool changes_state(const std::string& method) {
  return method != "GET" && method != "HEAD" && method != "OPTIONS";
}

}  // namespace

namespace {

// The media type of a Content-Type header: lower case, parameters and
// surrounding spaces cut.
std::string media_type(const std::string& content_type) {
  std::string media = lower(content_type.substr(0, content_type.find(';')));
  const auto space = [](unsigned char c) { return std::isspace(c) != 0; };
  media.erase(media.begin(), std::find_if_not(media.begin(), media.end(), space));
  media.erase(std::find_if_not(media.rbegin(), media.rend(), space).base(), media.end());
  return media;
}

}  // namespace

bool is_json_content_type(const std::string& content_type) {
  return media_type(content_type) == "application/json";
}

std::string required_content_type(const std::string& path) {
  return path == kUploadPath ? "application/octet-stream" : "application/json";
}

std::string origin_of_url(const std::string& url) {
  const std::size_t scheme_end = url.find("://");
  if (scheme_end == std::string::npos) return "";
  const std::size_t path_start = url.find_first_of("/?#", scheme_end + 3);
  return lower(url.substr(0, path_start));
}

RequestGuard::RequestGuard(const std::string& listen_host, int port) : port_(port) {
  const std::string host = lower(listen_host);
  if (host == "127.0.0.1" || host == "localhost" || host == "::1") {
    hosts_ = {"localhost", "127.0.0.1", "[::1]"};
  } else if (host.empty() || host == "0.0.0.0" || host == "::") {
    hosts_ = {"localhost"};
    any_ip_literal_ = true;
  } else {
    hosts_ = {host.find(':') != std::string::npos ? "[" + host + "]" : host};
  }
  for (const std::string& h : hosts_) {
    expected_ += (expected_.empty() ? "" : ", ") + fmt::format("{}:{}", h, port_);
  }
  if (any_ip_literal_) expected_ += ", or any of this machine's IP addresses with the port";
}

bool RequestGuard::host_allowed(const std::string& host) const {
  std::string name;
  int port = 0;
  if (!split_host(lower(host), name, port) || port != port_) return false;
  return hosts_.count(name) > 0 || (any_ip_literal_ && is_ip_literal(name));
}

RequestGuard::Refusal RequestGuard::refusal(const RequestFacts& r) const {
  if (!host_allowed(r.host)) {
    return {403, fmt::format("Host \"{}\" refused: this server answers only to {} (a page on "
                             "another name that resolves here is a DNS-rebinding attack)",
                             r.host, expected_)};
  }
  const bool state_changing = changes_state(r.method);
  if (!state_changing && !is_api(r.path)) return {};  // the page's own files
  // A browser names the page that sent the request; it must be this server's.
  const std::string own = "http://" + lower(r.host);
  const bool from_origin = !r.origin.empty();
  const std::string sender = from_origin ? lower(r.origin) : origin_of_url(r.referer);
  if ((from_origin || !r.referer.empty()) && sender != own) {
    return {403, fmt::format("cross-origin request refused: {} \"{}\" is not this server's "
                             "page ({}); the API obeys only its own page and clients that send "
                             "no Origin (curl, scripts)",
                             from_origin ? "Origin" : "Referer", from_origin ? r.origin : r.referer,
                             own)};
  }
  const std::string site = lower(r.sec_fetch_site);
  if (!site.empty() && site != "same-origin" && site != "none") {
    return {403, "cross-site request refused (Sec-Fetch-Site: " + r.sec_fetch_site +
                     "): the API answers only its own page"};
  }
  const std::string required = required_content_type(r.path);
  if (state_changing && media_type(r.content_type) != required) {
    return {415, fmt::format("{} {} needs \"Content-Type: {}\" (got \"{}\"); "
                             "with curl: -H 'Content-Type: {}'",
                             r.method, r.path, required, r.content_type, required)};
  }
  return {};
}

}  // namespace ris
