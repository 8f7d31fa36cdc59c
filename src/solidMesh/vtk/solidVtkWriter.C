/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "solidVtkWriter.H"
#include "foamVtkOutput.H"
#include "foamVtkFormatter.H"
#include "OSspecific.H"
#include "error.H"

#include <fstream>
#include <regex>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(solidVtkWriter, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

// One DataArray of nComp floats per tuple from flattened values
void writeFloats
(
    vtk::formatter& fmt,
    const word& name,
    const label nComp,
    const UList<scalar>& values
)
{
    fmt.openTag(vtk::fileTag::DATA_ARRAY)
        .xmlAttr("type", "Float32")
        .xmlAttr("Name", name)
        .xmlAttr("NumberOfComponents", nComp)
        .xmlAttr("format", fmt.name())
        .closeTag();
    fmt.writeSize(uint64_t(values.size())*sizeof(float));
    for (const scalar v : values)
    {
        fmt.write(float(v));
    }
    fmt.flush();
    fmt.endDataArray();
}

// One DataArray of labels
void writeLabels(vtk::formatter& fmt, const word& name, const labelUList& values)
{
    fmt.beginDataArray<label>(name);
    fmt.writeSize(uint64_t(values.size())*sizeof(label));
    vtk::writeList(fmt, values);
    fmt.flush();
    fmt.endDataArray();
}

// Points with z = 0, flattened
scalarList flatPoints(const UList<vector2D>& points)
{
    scalarList xyz(3*points.size());
    forAll(points, i)
    {
        xyz[3*i] = points[i].x();
        xyz[3*i + 1] = points[i].y();
        xyz[3*i + 2] = 0;
    }
    return xyz;
}

void writePoints(vtk::formatter& fmt, const UList<vector2D>& points)
{
    fmt.tag(vtk::fileTag::POINTS);
    writeFloats(fmt, "Points", 3, flatPoints(points));
    fmt.endTag(vtk::fileTag::POINTS);
}

//- The entries (file, time) of a .series file written by
//  vtk::seriesWriter: { "name" : "femdem_3.vtu", "time" : 0.002 }
DynamicList<fileNameInstant> readSeries(const fileName& file)
{
    DynamicList<fileNameInstant> entries;
    std::ifstream is(file);
    if (!is.good())
    {
        return entries;
    }
    std::stringstream buf;
    buf << is.rdbuf();
    const std::string text = buf.str();
    static const std::regex entry
    (
        R"re(\{\s*"name"\s*:\s*"([^"]*)"\s*,\s*"time"\s*:\s*([-+0-9.eE]+)\s*\})re"
    );
    for
    (
        std::sregex_iterator it(text.begin(), text.end(), entry), end;
        it != end;
        ++it
    )
    {
        entries.append
        (
            fileNameInstant(std::stod((*it)[2].str()), (*it)[1].str())
        );
    }
    return entries;
}

//- Index i of <name>_<i>.<ext>, -1 if the file is not of that form
label stepIndex(const fileName& file, const word& name)
{
    const std::string stem = file.nameLessExt();
    const std::string prefix = name + "_";
    label i = -1;
    if
    (
        stem.size() > prefix.size()
     && stem.compare(0, prefix.size(), prefix) == 0
     && readLabel(stem.substr(prefix.size()), i)
    )
    {
        return i;
    }
    return -1;
}

//- Keep the entries before startTime (and the one at it for a restart);
//  the series files hold the times to 6 significant digits
bool keepEntries
(
    DynamicList<fileNameInstant>& entries,
    const scalar startTime,
    const bool restart,
    const word& name,
    label& maxIndex
)
{
    const scalar tol = 1e-5*mag(startTime) + VSMALL;
    bool atStart = false;
    DynamicList<fileNameInstant> kept;
    for (const fileNameInstant& e : entries)
    {
        const bool before = e.value() < startTime - tol;
        const bool at = !before && e.value() <= startTime + tol;
        if (before || (restart && at))
        {
            kept.append(e);
            atStart = atStart || at;
            maxIndex = max(maxIndex, stepIndex(e.name(), name));
        }
    }
    entries.transfer(kept);
    return atStart;
}

autoPtr<vtk::formatter> openFile
(
    std::ofstream& os,
    const fileName& file,
    const vtk::formatType format
)
{
    mkDir(file.path());
    os.open(file);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot open " << file << " for writing" << exit(FatalError);
    }
    return vtk::newFormatter(os, format);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::solidVtkWriter::checkField
(
    const word& name,
    const label size,
    const label expected,
    const char* where
) const
{
    if (!inStep_)
    {
        FatalErrorInFunction
            << "Field " << name << " added outside beginStep/endStep of "
            << seriesName_ << exit(FatalError);
    }
    if (size != expected)
    {
        FatalErrorInFunction
            << where << " field " << name << " of " << seriesName_
            << " has " << size << " values for " << expected << ' ' << where
            << 's' << exit(FatalError);
    }
}


void Foam::solidVtkWriter::writePvd() const
{
    std::ofstream os(directory_/seriesName_ + ".pvd");
    autoPtr<vtk::formatter> fmt =
        vtk::newFormatter(os, vtk::formatType::INLINE_ASCII);
    fmt().xmlHeader()
        .openTag(vtk::fileTag::VTK_FILE)
        .xmlAttr("type", "Collection")
        .xmlAttr("version", "0.1")
        .closeTag();
    fmt().tag("Collection");
    for (label i = 0; i < series_.size(); ++i)
    {
        fmt().openTag(vtk::fileTag::DATA_SET)
            .xmlAttr("timestep", series_[i].value())
            .xmlAttr("file", series_[i].name())
            .closeTag(true);
    }
    fmt().endTag("Collection").endTag(vtk::fileTag::VTK_FILE);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidVtkWriter::solidVtkWriter
(
    const fileName& directory,
    const word& seriesName,
    const vtk::formatType format,
    const word& linesName
)
:
    directory_(directory),
    seriesName_(seriesName),
    format_(format),
    index_(0),
    inStep_(false),
    time_(0),
    stepHasLines_(false),
    linesName_(linesName.empty() ? word(seriesName + "Lines") : linesName),
    lineValueName_("value"),
    continued_(false)
{
    if (vtk::isLegacy(format) || vtk::isAppend(format))
    {
        FatalErrorInFunction
            << "Only inline XML formats are supported for " << seriesName
            << exit(FatalError);
    }
    mkDir(directory_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::solidVtkWriter::stepFile(const label i) const
{
    return directory_/seriesName_ + "_" + Foam::name(i) + ".vtu";
}


Foam::fileName Foam::solidVtkWriter::seriesFile() const
{
    return directory_/seriesName_ + ".vtu.series";
}


Foam::fileName Foam::solidVtkWriter::linesSeriesFile() const
{
    return directory_/linesName_ + ".vtp.series";
}


void Foam::solidVtkWriter::setLinesName(const word& linesName)
{
    if (index_ > 0 || inStep_)
    {
        FatalErrorInFunction
            << "setLinesName of " << seriesName_ << " after step "
            << index_ << " was started" << exit(FatalError);
    }
    linesName_ = linesName;
}


bool Foam::solidVtkWriter::continueSeries
(
    const scalar startTime,
    const bool restart
)
{
    if (index_ > 0 || inStep_)
    {
        FatalErrorInFunction
            << "continueSeries of " << seriesName_ << " after step "
            << index_ << " was started" << exit(FatalError);
    }
    series_ = readSeries(seriesFile());
    lineSeries_ = readSeries(linesSeriesFile());
    label maxIndex = -1;
    const bool atStart =
        keepEntries(series_, startTime, restart, seriesName_, maxIndex);
    keepEntries(lineSeries_, startTime, restart, linesName_, maxIndex);
    index_ = maxIndex + 1;
    continued_ = true;
    // Rewrite the series now: dropped steps leave them even if this run
    // writes no step
    if (isFile(seriesFile()))
    {
        vtk::seriesWriter::write(seriesFile(), series_);
        writePvd();
    }
    if (isFile(linesSeriesFile()))
    {
        vtk::seriesWriter::write(linesSeriesFile(), lineSeries_);
    }
    return atStart;
}


void Foam::solidVtkWriter::beginStep
(
    const scalar time,
    const UList<vector2D>& points,
    const UList<triangleVertices>& triangles
)
{
    if (inStep_)
    {
        FatalErrorInFunction
            << "beginStep of " << seriesName_ << " before endStep of step "
            << index_ << exit(FatalError);
    }
    for (const triangleVertices& tri : triangles)
    {
        for (const label v : tri)
        {
            if (v < 0 || v >= points.size())
            {
                FatalErrorInFunction
                    << "Triangle vertex " << v << " outside the "
                    << points.size() << " points of " << seriesName_
                    << exit(FatalError);
            }
        }
    }
    inStep_ = true;
    time_ = time;
    points_ = points;
    triangles_ = triangles;
    cellFieldNames_.clear();
    cellFieldComponents_.clear();
    cellFieldValues_.clear();
    pointFieldNames_.clear();
    pointFieldComponents_.clear();
    pointFieldValues_.clear();
    stepHasLines_ = false;
    lineFieldNames_.clear();
    lineFieldValues_.clear();
}


void Foam::solidVtkWriter::addLines
(
    const UList<vector2D>& points,
    const edgeList& lines,
    const UList<scalar>& lineValues,
    const word& valueName
)
{
    checkField
    (
        "lines", lineValues.size(),
        lineValues.size() ? lines.size() : label(0), "line"
    );
    stepHasLines_ = true;
    linePoints_ = points;
    lines_ = lines;
    lineValues_ = lineValues;
    lineValueName_ = valueName;
}


void Foam::solidVtkWriter::addLineField
(
    const word& name,
    const UList<scalar>& values
)
{
    if (!stepHasLines_)
    {
        FatalErrorInFunction
            << "line field " << name << " of " << seriesName_
            << " before addLines" << exit(FatalError);
    }
    checkField(name, values.size(), lines_.size(), "line");
    lineFieldNames_.append(name);
    lineFieldValues_.append(values);
}


void Foam::solidVtkWriter::addTriangleField
(
    const word& name,
    const UList<scalar>& values
)
{
    checkField(name, values.size(), triangles_.size(), "triangle");
    cellFieldNames_.append(name);
    cellFieldComponents_.append(1);
    cellFieldValues_.append(scalarList(values));
}


void Foam::solidVtkWriter::addTriangleField
(
    const word& name,
    const UList<label>& values
)
{
    checkField(name, values.size(), triangles_.size(), "triangle");
    scalarList v(values.size());
    forAll(values, i)
    {
        v[i] = values[i];
    }
    cellFieldNames_.append(name);
    cellFieldComponents_.append(1);
    cellFieldValues_.append(std::move(v));
}


void Foam::solidVtkWriter::addTriangleField
(
    const word& name,
    const UList<vector2D>& values
)
{
    checkField(name, values.size(), triangles_.size(), "triangle");
    cellFieldNames_.append(name);
    cellFieldComponents_.append(3);
    cellFieldValues_.append(flatPoints(values));
}


void Foam::solidVtkWriter::addTriangleField
(
    const word& name,
    const UList<symmTensor2D>& values
)
{
    checkField(name, values.size(), triangles_.size(), "triangle");
    // VTK symmetric tensor order: xx yy zz xy yz xz
    scalarList v(6*values.size(), Zero);
    forAll(values, i)
    {
        v[6*i] = values[i].xx();
        v[6*i + 1] = values[i].yy();
        v[6*i + 3] = values[i].xy();
    }
    cellFieldNames_.append(name);
    cellFieldComponents_.append(6);
    cellFieldValues_.append(std::move(v));
}


void Foam::solidVtkWriter::addPointField
(
    const word& name,
    const UList<scalar>& values
)
{
    checkField(name, values.size(), points_.size(), "point");
    pointFieldNames_.append(name);
    pointFieldComponents_.append(1);
    pointFieldValues_.append(scalarList(values));
}


void Foam::solidVtkWriter::addPointField
(
    const word& name,
    const UList<vector2D>& values
)
{
    checkField(name, values.size(), points_.size(), "point");
    pointFieldNames_.append(name);
    pointFieldComponents_.append(3);
    pointFieldValues_.append(flatPoints(values));
}


void Foam::solidVtkWriter::endStep()
{
    if (!inStep_)
    {
        FatalErrorInFunction
            << "endStep of " << seriesName_ << " without beginStep"
            << exit(FatalError);
    }

    const fileName file = stepFile(index_);
    {
        std::ofstream os;
        autoPtr<vtk::formatter> fmtPtr = openFile(os, file, format_);
        vtk::formatter& fmt = fmtPtr();

        fmt.xmlHeader()
            .beginVTKFile<vtk::fileTag::UNSTRUCTURED_GRID>();

        fmt.beginFieldData();
        fmt.writeTimeValue(time_);
        fmt.endFieldData();

        fmt.tag
        (
            vtk::fileTag::PIECE,
            vtk::fileAttr::NUMBER_OF_POINTS, points_.size(),
            vtk::fileAttr::NUMBER_OF_CELLS, triangles_.size()
        );

        writePoints(fmt, points_);

        fmt.tag(vtk::fileTag::CELLS);
        labelList connectivity(3*triangles_.size());
        labelList offsets(triangles_.size());
        forAll(triangles_, t)
        {
            for (label k = 0; k < 3; ++k)
            {
                connectivity[3*t + k] = triangles_[t][k];
            }
            offsets[t] = 3*(t + 1);
        }
        writeLabels(fmt, "connectivity", connectivity);
        writeLabels(fmt, "offsets", offsets);
        {
            List<uint8_t> types(triangles_.size(), vtk::cellType::VTK_TRIANGLE);
            fmt.beginDataArray<uint8_t>("types");
            fmt.writeSize(uint64_t(types.size()));
            vtk::writeList(fmt, types);
            fmt.flush();
            fmt.endDataArray();
        }
        fmt.endTag(vtk::fileTag::CELLS);

        fmt.beginCellData();
        forAll(cellFieldNames_, i)
        {
            writeFloats
            (
                fmt, cellFieldNames_[i], cellFieldComponents_[i],
                cellFieldValues_[i]
            );
        }
        fmt.endCellData();

        fmt.beginPointData();
        forAll(pointFieldNames_, i)
        {
            writeFloats
            (
                fmt, pointFieldNames_[i], pointFieldComponents_[i],
                pointFieldValues_[i]
            );
        }
        fmt.endPointData();

        fmt.endPiece();
        fmt.endTag(vtk::fileTag::UNSTRUCTURED_GRID);
        fmt.endVTKFile();
    }

    series_.append(fileNameInstant(time_, file.name()));
    vtk::seriesWriter::write(seriesFile(), series_);
    writePvd();

    if (stepHasLines_)
    {
        const fileName linesFile =
            directory_/linesName_ + "_" + Foam::name(index_) + ".vtp";
        writeLines
        (
            linesFile, linePoints_, lines_, lineValues_, format_,
            lineValueName_, lineFieldNames_, lineFieldValues_
        );
        lineSeries_.append(fileNameInstant(time_, linesFile.name()));
        vtk::seriesWriter::write(linesSeriesFile(), lineSeries_);
    }

    ++index_;
    inStep_ = false;
}


void Foam::solidVtkWriter::writeLines
(
    const fileName& file,
    const UList<vector2D>& points,
    const edgeList& lines,
    const UList<scalar>& lineValues,
    const vtk::formatType format,
    const word& valueName,
    const UList<word>& fieldNames,
    const UList<scalarList>& fieldValues
)
{
    if (lineValues.size() && lineValues.size() != lines.size())
    {
        FatalErrorInFunction
            << lineValues.size() << " values for " << lines.size()
            << " lines in " << file << exit(FatalError);
    }
    forAll(fieldValues, k)
    {
        if (fieldValues[k].size() != lines.size())
        {
            FatalErrorInFunction
                << fieldValues[k].size() << " values of " << fieldNames[k]
                << " for " << lines.size() << " lines in " << file
                << exit(FatalError);
        }
    }

    // Only the points that the lines use, in order of first use
    labelList newIndex(points.size(), -1);
    DynamicList<vector2D> used(2*lines.size());
    labelList connectivity(2*lines.size());
    forAll(lines, i)
    {
        for (label k = 0; k < 2; ++k)
        {
            const label p = lines[i][k];
            if (p < 0 || p >= points.size())
            {
                FatalErrorInFunction
                    << "Line " << i << " uses point " << p << " outside the "
                    << points.size() << " points, writing " << file
                    << exit(FatalError);
            }
            if (newIndex[p] < 0)
            {
                newIndex[p] = used.size();
                used.append(points[p]);
            }
            connectivity[2*i + k] = newIndex[p];
        }
    }
    labelList offsets(lines.size());
    forAll(offsets, i)
    {
        offsets[i] = 2*(i + 1);
    }

    std::ofstream os;
    autoPtr<vtk::formatter> fmtPtr = openFile(os, file, format);
    vtk::formatter& fmt = fmtPtr();

    fmt.xmlHeader()
        .beginVTKFile<vtk::fileTag::POLY_DATA>();
    fmt.tag
    (
        vtk::fileTag::PIECE,
        vtk::fileAttr::NUMBER_OF_POINTS, used.size(),
        vtk::fileAttr::NUMBER_OF_LINES, lines.size()
    );
    writePoints(fmt, used);
    fmt.tag(vtk::fileTag::LINES);
    writeLabels(fmt, "connectivity", connectivity);
    writeLabels(fmt, "offsets", offsets);
    fmt.endTag(vtk::fileTag::LINES);
    if (lineValues.size() || fieldValues.size())
    {
        fmt.beginCellData();
        if (lineValues.size())
        {
            writeFloats(fmt, valueName, 1, lineValues);
        }
        forAll(fieldValues, k)
        {
            writeFloats(fmt, fieldNames[k], 1, fieldValues[k]);
        }
        fmt.endCellData();
    }
    fmt.endPiece();
    fmt.endTag(vtk::fileTag::POLY_DATA);
    fmt.endVTKFile();
}


// ************************************************************************* //
