// DefectSitesJson: each site's kind, place with its standard uncertainty
// (a span's ends), spread, crossings and times.
#include "core/detector/DefectSitesJson.h"

namespace tactiscope::core::detector {

void writeSitesJson(text::JsonWriter& json, const SiteGrouping& grouping)
{
    json.key("sites").beginArray();
    for (const DefectSite& site : grouping.sites) {
        json.beginObject();
        json.key("kind").value(site.kind == SiteKind::Site   ? "site"
                               : site.kind == SiteKind::Span ? "span"
                                                             : "unplaced");
        json.key("position_mm");
        if (site.position_m)
            json.value(*site.position_m * 1e3);
        else
            json.null();
        json.key("position_u_mm");
        if (site.position_m)
            json.value(site.position_u_m * 1e3);
        else
            json.null();
        if (site.kind == SiteKind::Span) {
            json.key("from_mm").value(site.from_m * 1e3);
            json.key("to_mm").value(site.to_m * 1e3);
        }
        json.key("spread_mm").value(site.spread_m * 1e3);
        json.key("crossings").value(static_cast<long long>(site.crossings.size()));
        json.key("a_then_b").value(static_cast<long long>(site.forward));
        json.key("b_then_a").value(static_cast<long long>(site.backward));
        json.key("first_s").value(site.first_s);
        json.key("last_s").value(site.last_s);
        json.endObject();
    }
    json.endArray();
    json.key("sites_method").value(grouping.method);
}

}  // namespace tactiscope::core::detector
