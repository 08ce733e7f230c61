// SVG and PDF of the plan with the path, from the shared drawing (PlanDrawing.h). The PDF
// is a minimal single-page PDF 1.4 (vector paths, the standard Helvetica font) written by
// hand so that the CLI needs no Qt; it passes `qpdf --check`.
#include "formats/Export.h"
#include "formats/PlanDrawing.h"
#include "formats/WriterSupport.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace fc {

using formats::fixedNumber;
using formats::PlanDrawing;
using formats::Rgb;

namespace {

std::string xmlEscaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string hexColour(Rgb c) {
    char buffer[8];
    auto byte = [](double v) {
        return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
    };
    std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return buffer;
}

// Printable ASCII for the standard PDF fonts, with ( ) \ escaped.
std::string pdfText(const std::string& text) {
    std::string out;
    for (unsigned char c : text) {
        if (c == '(' || c == ')' || c == '\\')
            out += '\\';
        out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
    }
    return out;
}

std::string pdfColour(Rgb c, const char* op) {
    return fixedNumber(c.r, 3) + " " + fixedNumber(c.g, 3) + " " + fixedNumber(c.b, 3) + " " + op +
           "\n";
}

} // namespace

std::string planToSvg(const Plan& plan, const CoveragePath& path, const PathExportInfo& info) {
    const PlanDrawing d = formats::drawingOf(plan, path, info);
    const double width = d.bounds.maxX - d.bounds.minX, height = d.bounds.maxY - d.bounds.minY;
    const double mmPerMetre = 250.0 / std::max(width, height); // the longer side 250 mm
    auto n = [](double v) { return fixedNumber(v, 4); };
    std::ostringstream out;
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\""
        << n(width * mmPerMetre) << "mm\" height=\"" << n(height * mmPerMetre) << "mm\" viewBox=\""
        << n(d.bounds.minX) << ' ' << n(-d.bounds.maxY) << ' ' << n(width) << ' ' << n(height)
        << "\">\n"
        << "<title>" << xmlEscaped(d.title) << "</title>\n"
        << "<desc>" << xmlEscaped(d.caption) << (d.legend.empty() ? "" : "; ")
        << xmlEscaped(d.legend) << "; viewBox in metres with y flipped (SVG y = -plan y)</desc>\n"
        << "<g transform=\"scale(1,-1)\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
    for (const formats::DrawItem& item : d.items) {
        out << (item.closed ? "<polygon" : "<polyline") << " points=\"";
        for (size_t i = 0; i < item.points.size(); ++i)
            out << (i ? " " : "") << n(item.points[i].x) << ',' << n(item.points[i].y);
        out << "\" fill=\"" << (item.filled ? hexColour(item.fill) : "none") << "\" stroke=\""
            << (item.width > 0 ? hexColour(item.stroke) : "none") << "\" stroke-width=\""
            << n(item.width) << "\"";
        if (item.dash > 0)
            out << " stroke-dasharray=\"" << n(item.dash) << "\"";
        out << "/>\n";
    }
    out << "</g>\n";
    for (const formats::DrawLabel& label : d.labels)
        out << "<text x=\"" << n(label.at.x) << "\" y=\"" << n(-label.at.y) << "\" font-size=\""
            << n(label.size) << "\" font-family=\"sans-serif\">" << xmlEscaped(label.text)
            << "</text>\n";
    out << "</svg>\n";
    return out.str();
}

std::string planToPdf(const Plan& plan, const CoveragePath& path, const PathExportInfo& info) {
    const PlanDrawing d = formats::drawingOf(plan, path, info);
    const double width = d.bounds.maxX - d.bounds.minX, height = d.bounds.maxY - d.bounds.minY;
    // The drawing fits 780 x 500 pt; 40 pt margins, 40 pt more at the top for the text.
    const double scale = std::min(780.0 / width, 500.0 / height);
    const double pageWidth = width * scale + 80, pageHeight = height * scale + 120;
    auto n = [](double v) { return fixedNumber(v, 4); };

    std::ostringstream content;
    content << "q\n"
            << n(scale) << " 0 0 " << n(scale) << ' ' << n(40 - d.bounds.minX * scale) << ' '
            << n(40 - d.bounds.minY * scale) << " cm\n1 J 1 j\n";
    for (const formats::DrawItem& item : d.items) {
        content << n(item.width) << " w\n"
                << (item.dash > 0 ? "[" + n(item.dash) + "] 0 d\n" : std::string("[] 0 d\n"));
        if (item.filled)
            content << pdfColour(item.fill, "rg");
        content << pdfColour(item.stroke, "RG");
        for (size_t i = 0; i < item.points.size(); ++i)
            content << n(item.points[i].x) << ' ' << n(item.points[i].y) << (i ? " l\n" : " m\n");
        content << (item.closed ? (item.filled ? "b\n" : "s\n") : "S\n");
    }
    content << "Q\n0 0 0 rg\n";
    for (const formats::DrawLabel& label : d.labels)
        content << "BT /F1 " << n(label.size * scale) << " Tf "
                << n(40 + (label.at.x - d.bounds.minX) * scale) << ' '
                << n(40 + (label.at.y - d.bounds.minY) * scale) << " Td (" << pdfText(label.text)
                << ") Tj ET\n";
    content << "BT /F1 14 Tf 40 " << n(pageHeight - 40) << " Td (" << pdfText(d.title)
            << ") Tj ET\n"
            << "BT /F1 8 Tf 40 " << n(pageHeight - 56) << " Td (" << pdfText(d.caption)
            << ") Tj ET\n"
            << "BT /F1 8 Tf 40 " << n(pageHeight - 67) << " Td (" << pdfText(d.legend)
            << ") Tj ET\n";
    const std::string stream = content.str();

    std::vector<std::string> objects = {
        "<< /Type /Catalog /Pages 2 0 R >>",
        "<< /Type /Pages /Kids [3 0 R] /Count 1 >>",
        "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 " + n(pageWidth) + " " + n(pageHeight) +
            "] /Contents 4 0 R /Resources << /Font << /F1 5 0 R >> >> >>",
        "<< /Length " + std::to_string(stream.size()) + " >>\nstream\n" + stream + "endstream",
        "<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>",
        "<< /Title (" + pdfText(d.title) + ") /Subject (" + pdfText(d.caption + "; " + d.legend) +
            ") /Producer (FloorCover) >>"};
    std::string pdf = "%PDF-1.4\n%\xE2\xE3\xCF\xD3\n";
    std::vector<size_t> offsets;
    for (size_t i = 0; i < objects.size(); ++i) {
        offsets.push_back(pdf.size());
        pdf += std::to_string(i + 1) + " 0 obj\n" + objects[i] + "\nendobj\n";
    }
    const size_t xref = pdf.size();
    pdf += "xref\n0 " + std::to_string(objects.size() + 1) + "\n0000000000 65535 f \n";
    for (size_t offset : offsets) {
        char entry[24];
        std::snprintf(entry, sizeof entry, "%010zu 00000 n \n", offset);
        pdf += entry;
    }
    pdf += "trailer\n<< /Size " + std::to_string(objects.size() + 1) +
           " /Root 1 0 R /Info 6 0 R >>\nstartxref\n" + std::to_string(xref) + "\n%%EOF\n";
    return pdf;
}

} // namespace fc
