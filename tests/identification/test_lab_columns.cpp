// Lab files: columns with units in the name or in a units row, other names mapped with
// --columns, values converted to SI and never taken as they are (lab_columns.hpp).
#include <gtest/gtest.h>

#include "temp_files.hpp"

#include <cmath>
#include <fstream>
#include <string>

#include "contensou/friction/error.hpp"
#include "contensou/identification/lab_columns.hpp"
#include "contensou/identification/measured_data.hpp"

using namespace contensou;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const std::string path = contensou::test::temp_path(name);
  std::ofstream(path) << text;
  return path;
}

// The message of the ParseError reading `text` throws ("" if none).
std::string error_of(const std::string& text, const ColumnRenames& renames = {},
                     KeyStyle style = KeyStyle::command_line) {
  try {
    read_measured_csv(write("lab_bad.csv", text), renames, style);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

// Two rows in SI, the oracle every unit variant must reproduce.
const char* kSi =
    "vx_mps,vy_mps,omega_radps,Fx_N,Fy_N,Mz_Nm,Fz_N\n"
    "1.5,-0.25,10,-1200,35,-7.5,4000\n"
    "0,0.5,-3,0,-800,2.25,4100\n";

void expect_same(const MeasuredData& a, const MeasuredData& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const MeasuredPoint &p = a.points[i], &q = b.points[i];
    EXPECT_NEAR(p.kinematics.vx, q.kinematics.vx, 1e-12 * (1 + std::abs(q.kinematics.vx)));
    EXPECT_NEAR(p.kinematics.vy, q.kinematics.vy, 1e-12 * (1 + std::abs(q.kinematics.vy)));
    EXPECT_NEAR(p.kinematics.omega, q.kinematics.omega, 1e-12 * (1 + std::abs(q.kinematics.omega)));
    for (int c = 0; c < kChannels; ++c) {
      ASSERT_EQ(p.force[c].has_value(), q.force[c].has_value());
      if (p.force[c]) {
        EXPECT_NEAR(*p.force[c], *q.force[c], 1e-9 * (1 + std::abs(*q.force[c])));
      }
    }
    ASSERT_TRUE(p.normal_load && q.normal_load);
    EXPECT_NEAR(*p.normal_load, *q.normal_load, 1e-9 * *q.normal_load);
  }
}

}  // namespace

TEST(LabColumns, UnitsInTheNameAreConvertedToSi) {
  const MeasuredData si = read_measured_csv(write("lab_si.csv", kSi));
  EXPECT_TRUE(si.column_notes.empty());
  // 1.5 m/s = 5.4 km/h; 10 rad/s = 600/pi deg/s = 300/pi rpm; forces in kN, moment in N mm.
  const std::string brackets =
      "vx [km/h],vy (km/h),omega [deg/s],Fx [kN],Fy [kN],Mz [N mm],Fz [kN]\n"
      "5.4,-0.9," +
      std::to_string(10 * 180 / M_PI) + ",-1.2,0.035,-7500,4\n" + "0,1.8," +
      std::to_string(-3 * 180 / M_PI) + ",0,-0.8,2250,4.1\n";
  const MeasuredData b = read_measured_csv(write("lab_brackets.csv", brackets));
  // std::to_string keeps 6 decimals: compare omega at that precision.
  ASSERT_EQ(b.points.size(), 2u);
  EXPECT_NEAR(b.points[0].kinematics.omega, 10.0, 1e-7);
  MeasuredData b_exact = b;
  for (std::size_t i = 0; i < 2; ++i)
    b_exact.points[i].kinematics.omega = si.points[i].kinematics.omega;
  expect_same(b_exact, si);
  ASSERT_EQ(b.column_notes.size(), 7u);
  EXPECT_NE(b.column_notes[0].find("vx_mps from 'vx [km/h]' (column 1) in km/h, x 0.277778"),
            std::string::npos)
      << b.column_notes[0];

  const std::string underscores =
      "vx_kmh,vy_mps,omega_rpm,Fx_kN,Fy_N,Mz_kNm,Fz_N\n"
      "5.4,-0.25," +
      std::to_string(10 * 60 / (2 * M_PI)) + ",-1.2,35,-0.0075,4000\n" + "0,0.5," +
      std::to_string(-3 * 60 / (2 * M_PI)) + ",0,-800,0.00225,4100\n";
  const MeasuredData u = read_measured_csv(write("lab_underscores.csv", underscores));
  EXPECT_NEAR(u.points[1].kinematics.omega, -3.0, 1e-7);
  MeasuredData u_exact = u;
  for (std::size_t i = 0; i < 2; ++i)
    u_exact.points[i].kinematics.omega = si.points[i].kinematics.omega;
  expect_same(u_exact, si);
}

TEST(LabColumns, AUnitsRowIsReadAndChecked) {
  const MeasuredData si = read_measured_csv(write("lab_si.csv", kSi));
  const std::string with_row =
      "vx,vy,omega,Fx,Fy,Mz,Fz\n"
      "km/h,m/s,rad/s,kN,N,N m,kN\n"
      "5.4,-0.25,10,-1.2,35,-7.5,4\n"
      "0,0.5,-3,0,-800,2.25,4.1\n";
  const MeasuredData r = read_measured_csv(write("lab_units_row.csv", with_row));
  expect_same(r, si);
  EXPECT_EQ(r.points[0].line, 3);  // the units row is not data
  // A units row that contradicts the header's unit: line 2, the column named.
  const std::string clash = error_of(
      "vx [km/h],vy_mps,omega_radps,Fx_N\n"
      "m/s,m/s,rad/s,N\n"
      "1,2,3,4\n");
  EXPECT_NE(clash.find(":2: column 'vx [km/h]' (1): the units row says 'm/s'"), std::string::npos)
      << clash;
  // A glitch in the first data row is not a units row: the usual "not a number" at its cell.
  const std::string glitch = error_of(
      "vx_mps,vy_mps,omega_radps,Fx_N\n"
      "1,2,x3,4\n");
  EXPECT_NE(glitch.find(":2: column 'omega_radps' (3): not a number: 'x3'"), std::string::npos)
      << glitch;
  // Bare names without a units row: read as SI, and the report says so.
  const MeasuredData bare = read_measured_csv(write("lab_bare.csv", "vx,vy,omega,Fx\n1,2,3,4\n"));
  ASSERT_EQ(bare.column_notes.size(), 4u);
  EXPECT_NE(bare.column_notes[0].find("no unit given: read as m/s"), std::string::npos);
}

TEST(LabColumns, UnknownOrWrongUnitsAreRefusedWithTheUnitsAccepted) {
  const std::string lbf = error_of("vx_mps,vy_mps,omega_radps,Fx [lbf]\n1,2,3,4\n");
  EXPECT_NE(lbf.find("column 'Fx [lbf]' (4): unit 'lbf' of Fx is not one this reader converts "
                     "(Fx: N, kN)"),
            std::string::npos)
      << lbf;
  const std::string kind = error_of("vx_mps,vy_mps,omega_radps,Mz [N]\n1,2,3,4\n");
  EXPECT_NE(kind.find("'N' is not a unit of Mz (Mz: N m, kN m, N mm)"), std::string::npos) << kind;
  const std::string twice = error_of("vx_kmh,vx [m/s],vy_mps,omega_radps,Fx_N\n1,1,2,3,4\n");
  EXPECT_NE(twice.find("two columns for vx"), std::string::npos) << twice;
  // The SI-named column wins over the same quantity in another unit (logged twice by a rig).
  const MeasuredData both = read_measured_csv(
      write("lab_both.csv", "vx_mps,vy_mps,omega_rpm,omega_radps,Fx_N\n1,2,600,62.832,4\n"));
  EXPECT_EQ(both.points[0].kinematics.omega, 62.832);
  // A near miss is still refused, now with the way to map it.
  const std::string miss = error_of("vx_mps,vy_mps,omega_radps,Fxx_N,Fy_N\n1,2,3,4,5\n");
  EXPECT_NE(miss.find("did you mean 'Fx_N'"), std::string::npos) << miss;
}

TEST(LabColumns, RenamesMapOtherNamesWithTheirUnits) {
  const std::string text =
      "Speed [km/h],Side slip,Wheel rate (rpm),Long. force [kN],Torque\n"
      "36,0,600,-2,-7.5\n";
  const ColumnRenames renames =
      parse_column_renames("vx=Speed, vy=Side slip,omega=Wheel rate,Fx=Long. force,Mz=Torque");
  const MeasuredData d = read_measured_csv(write("lab_renamed.csv", text), renames);
  ASSERT_EQ(d.points.size(), 1u);
  EXPECT_NEAR(d.points[0].kinematics.vx, 10.0, 1e-12);
  EXPECT_NEAR(d.points[0].kinematics.omega, 20 * M_PI, 1e-12);
  EXPECT_NEAR(*d.points[0].force[0], -2000.0, 1e-9);
  EXPECT_NEAR(*d.points[0].force[2], -7.5, 1e-12);
  const std::string none = error_of(text, parse_column_renames("vx=Velocity"));
  EXPECT_NE(none.find("--columns vx=Velocity: the header has no column 'Velocity'"),
            std::string::npos)
      << none;
  EXPECT_THROW(parse_column_renames("speed=Speed"), std::invalid_argument);
  EXPECT_THROW(parse_column_renames("vx"), std::invalid_argument);
}

// The same refusals from Python name its keyword (columns={...}), never the app's --columns.
TEST(LabColumns, MessagesNameTheRenameAsEachFrontEndWritesIt) {
  const std::string text = "Speed,vy_mps,Rate,Fx_N\n1,0,3,4\n";
  const std::string app = error_of(text, parse_column_renames("vx=Speed"));
  EXPECT_NE(app.find("(or give its name: --columns omega=NAME)"), std::string::npos) << app;
  const std::string py =
      error_of(text, parse_column_renames("vx=Speed", KeyStyle::python), KeyStyle::python);
  EXPECT_NE(py.find("(or give its name: columns={'omega': 'NAME'})"), std::string::npos) << py;
  EXPECT_EQ(py.find("--columns"), std::string::npos) << py;
  const std::string missing = error_of(text, {{"vx", "Velocity"}}, KeyStyle::python);
  EXPECT_NE(missing.find("columns={'vx': 'Velocity'}: the header has no column 'Velocity'"),
            std::string::npos)
      << missing;
  ColumnRenames renames;
  try {
    add_column_rename(renames, "speed", "Speed", KeyStyle::python);
    ADD_FAILURE() << "an unknown quantity was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(
        std::string(e.what()).rfind("columns={'speed': 'Speed'}: 'speed' is not a quantity", 0), 0u)
        << e.what();
  }
  add_column_rename(renames, " Mz ", "Torque, N=m", KeyStyle::python);  // any characters
  ASSERT_EQ(renames.size(), 1u);
  EXPECT_EQ(renames[0], (std::pair<std::string, std::string>{"Mz", "Torque, N=m"}));
}

TEST(LabColumns, TheLoadComesFromTheFzColumnInAnyUnit) {
  const MeasuredData d = read_measured_csv(
      write("lab_fz.csv", "vx_mps,vy_mps,omega_radps,Fx_N,Fz [kN]\n1,0,3,4,5\n2,0,3,4,5.5\n"));
  const std::optional<LoadFromData> load = normal_load_from_data(d);
  ASSERT_TRUE(load);
  EXPECT_NEAR(load->mean_n, 5250.0, 1e-9);
  EXPECT_NEAR(load->spread, 250.0 / 5250.0, 1e-12);
  EXPECT_EQ(load->rows, 2);
  const MeasuredData no_fz =
      read_measured_csv(write("lab_nofz.csv", "vx_mps,vy_mps,omega_radps,Fx_N\n1,0,3,4\n"));
  EXPECT_FALSE(normal_load_from_data(no_fz));
  // A load that is not positive after conversion is refused at its cell.
  const std::string bad = error_of("vx_mps,vy_mps,omega_radps,Fx_N,Fz_kN\n1,0,3,4,-1\n");
  EXPECT_NE(bad.find(":2: column 'Fz_kN' (5): -1000 must be positive"), std::string::npos) << bad;
}

// The checks of a measured-diagram header are lab_columns' alone (resolve_measured_columns):
// on header cells, without a CSV table, with the messages the file reader gives.
TEST(LabColumns, MeasuredHeaderChecksNeedNoTable) {
  const auto refusal = [](const std::vector<std::string>& cells) {
    try {
      resolve_measured_columns(LabHeader{cells, nullptr, "h.csv", 3, 0});
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(refusal({"1", "2", "3"}).find("h.csv:3: the first row holds numbers"),
            std::string::npos);
  const std::string missing = refusal({"vx_mps", "vy_mps", "omga_radps", "Fx_N"});
  EXPECT_NE(missing.find("missing required column 'omega_radps' (did you mean 'omga_radps'?)"),
            std::string::npos)
      << missing;
  const std::string miss = refusal({"vx_mps", "vy_mps", "omega_radps", "Fxx_N", "Fy_N"});
  EXPECT_NE(miss.find("column 'Fxx_N' (4) is not a column this reader knows: did you mean "
                      "'Fx_N'?"),
            std::string::npos)
      << miss;
  EXPECT_NE(refusal({"vx_mps", "vy_mps", "omega_radps", "t_s"}).find("no measured channel"),
            std::string::npos);
  const LabColumns ok = resolve_measured_columns(
      LabHeader{{"t_s", "vx_mps", "vy_mps", "omega_radps", "Mz [N mm]"}, nullptr, "h.csv", 1, 0});
  EXPECT_EQ(ok[MeasuredQuantity::Mz].index, 4);
  EXPECT_DOUBLE_EQ(ok[MeasuredQuantity::Mz].to_si, 1e-3);
}

// A column no channel reads but that looks like one (a misspelt name, a force unit) would lose
// its data without a word: refused, naming the column and the channel it resembles.
TEST(LabColumns, AColumnThatLooksLikeAChannelIsNeverDroppedUnread) {
  const std::string rows = "1,0,10,-1.2,35,-7.5\n2,0,10,-1.3,36,-7.4\n";
  const auto refusal = [&](const std::string& fx_header) {
    return error_of("vx_mps,vy_mps,omega_radps," + fx_header + ",Fy_N,Mz_Nm\n" + rows);
  };
  const std::string fxx = refusal("Fxx [kN]");
  EXPECT_NE(fxx.find("column 'Fxx [kN]' (4) is not a column this reader knows: did you mean "
                     "'Fx_N'?"),
            std::string::npos)
      << fxx;
  EXPECT_NE(fxx.find("--columns Fx='Fxx [kN]'"), std::string::npos) << fxx;
  for (const std::string h : {"Force X [kN]", "Fx [kN]x"}) {
    const std::string e = refusal(h);
    EXPECT_NE(e.find("column '" + h + "' (4): holds a force (kN) that no channel reads"),
              std::string::npos)
        << e;
  }
  // The same channel named twice: which column holds it?
  const std::string twice = error_of("vx_mps,vy_mps,omega_radps,Fx_N,Fx_N,Mz_Nm\n" + rows);
  EXPECT_NE(twice.find(":1:5: duplicate column 'Fx_N' (columns 4 and 5)"), std::string::npos)
      << twice;
  // Declared, the same columns are read: mapped, kept or left out.
  const std::string path = write("lab_force_x.csv",
                                 "vx_mps,vy_mps,omega_radps,Force X [kN],"
                                 "Fy_N,Mz_Nm\n" +
                                     rows);
  const MeasuredData mapped = read_measured_csv(path, {{"Fx", "Force X [kN]"}});
  EXPECT_DOUBLE_EQ(*mapped.points[1].force[0], -1300.0);
  const MeasuredData kept = read_measured_csv(path, {{"extra", "Force X [kN]"}});
  ASSERT_EQ(kept.recorded.size(), 1u);
  EXPECT_DOUBLE_EQ(kept.points[1].recorded[0], -1300.0);  // kN to N
  EXPECT_FALSE(kept.points[1].force[0].has_value());
  const MeasuredData left = read_measured_csv(path, {{"ignore", "Force X [kN]"}});
  EXPECT_TRUE(left.recorded.empty());
  ASSERT_EQ(left.columns_not_read.size(), 1u);
  EXPECT_NE(left.columns_not_read[0].find("'Force X [kN]' (column 4)"), std::string::npos);
}

// Every other column is accounted for: numeric ones recorded in SI (a temperature with its
// offset), text and unnamed ones listed as not read, Mx recorded though it holds a moment.
TEST(LabColumns, EveryOtherColumnIsRecordedOrListedAsNotRead) {
  const MeasuredData d = read_measured_csv(
      write("lab_extra.csv",
            ",vx_mps,vy_mps,omega_radps,Fx_N,T [degC],p_tire [bar],note,Mx [N m],camber [deg]\n"
            "0,1,0,10,-1200,25,2.5,ok,12,1.5\n"
            "1,2,0,10,-1300,,2.4,ok,13,-1.5\n"));
  ASSERT_EQ(d.recorded.size(), 4u);
  EXPECT_EQ(d.recorded[0].name, "T");
  EXPECT_EQ(d.recorded[0].kind, "temperature");
  EXPECT_EQ(d.recorded[0].si_unit, "K");
  EXPECT_DOUBLE_EQ(d.points[0].recorded[0], 298.15);
  EXPECT_TRUE(std::isnan(d.points[1].recorded[0]));  // an empty cell
  EXPECT_DOUBLE_EQ(d.points[1].recorded[1], 2.4e5);  // bar to Pa
  EXPECT_EQ(d.recorded[2].header, "Mx [N m]");
  EXPECT_DOUBLE_EQ(d.points[0].recorded[3], 1.5 * M_PI / 180.0);
  ASSERT_EQ(d.columns_not_read.size(), 2u);
  EXPECT_EQ(d.columns_not_read[0], "column 1 (unnamed)");
  EXPECT_EQ(d.columns_not_read[1], "'note' (column 8): text");
  // A bare "T" whose units row says degC is a temperature, not the time t.
  const MeasuredData row = read_measured_csv(
      write("lab_extra_row.csv", "vx,vy,omega,Fx,T\nm/s,m/s,rad/s,N,degC\n1,0,10,-1200,20\n"));
  EXPECT_FALSE(row.points[0].time.has_value());
  ASSERT_EQ(row.recorded.size(), 1u);
  EXPECT_DOUBLE_EQ(row.points[0].recorded[0], 293.15);
  // The same rate twice, in rad/s and in rpm: the SI one is read, the other listed.
  const MeasuredData twice = read_measured_csv(
      write("lab_twice.csv", "vx_mps,vy_mps,omega_radps,omega [rpm],Fx_N\n1,0,10,95.5,-1200\n"));
  ASSERT_EQ(twice.columns_not_read.size(), 1u);
  EXPECT_EQ(twice.columns_not_read[0],
            "'omega [rpm]' (column 4): omega is read from 'omega_radps' (column 3); every row "
            "checked to hold the same value");
}

// A second column of a channel beside its SI column is read only as a check: it must repeat the
// SI column's values to the digits it writes, else it holds another channel and is refused
// (the row named); one in a unit the channel does not have (Fx_raw) is refused until declared.
TEST(LabColumns, ASecondColumnOfAChannelMustHoldTheSameValues) {
  const std::string head = "vx_mps,vy_mps,omega_radps,Fx_N,Fy_N,";
  const std::string same =
      error_of(head + "Fx [kN]\n1,0,10,-1234.4,35,-1.234\n2,0,10,-80,36,-0.08\n");
  EXPECT_EQ(same, "");  // 1.234 kN written to the newton: the same channel
  const std::string other = error_of(head + "Fx [N]\n1,0,10,-1200,35,-1200\n2,0,10,-80,36,36\n");
  EXPECT_NE(
      other.find("lab_bad.csv:3: column 'Fx [N]' (6): is a second Fx beside 'Fx_N' (column 4), "
                 "but this row differs: 36 N here = 36 N, -80 N in 'Fx_N'"),
      std::string::npos)
      << other;
  EXPECT_NE(other.find("--columns extra='Fx [N]'"), std::string::npos) << other;
  const std::string scaled = error_of(head + "Fx [kN]\n1,0,10,-1200,35,-1.212\n");
  EXPECT_NE(scaled.find(":2: column 'Fx [kN]' (6): is a second Fx"), std::string::npos) << scaled;
  const std::string raw = error_of(head + "Fx_raw\n1,0,10,-1200,35,-1212\n");
  EXPECT_NE(raw.find("column 'Fx_raw' (6): is a second Fx beside 'Fx_N' in 'raw', which is not a "
                     "unit of Fx"),
            std::string::npos)
      << raw;
  // Declared, the same column is kept or left out; a units row gives a twin its unit.
  const std::string path = write("lab_raw.csv", head + "Fx_raw\n1,0,10,-1200,35,-1212\n");
  const MeasuredData kept = read_measured_csv(path, {{"extra", "Fx_raw"}});
  ASSERT_EQ(kept.recorded.size(), 1u);
  EXPECT_DOUBLE_EQ(kept.points[0].recorded[0], -1212.0);
  EXPECT_EQ(read_measured_csv(path, {{"ignore", "Fx_raw"}}).recorded.size(), 0u);
  EXPECT_EQ(error_of(head + "Fx\nm/s,m/s,rad/s,N,N,kN\n1,0,10,-1200,35,-1.2\n"), "");
  EXPECT_NE(error_of(head + "Fx\nm/s,m/s,rad/s,N,N,N\n1,0,10,-1200,35,-1.2\n").find("differs"),
            std::string::npos);
}

// Missing values as labs write them (n/a, NA, -, nan, empty) are missing in that cell only, and
// counted a column; in the kinematics they are refused.
TEST(LabColumns, MissingValueSpellingsAreMissingCellByCell) {
  const MeasuredData d = read_measured_csv(
      write("lab_missing.csv",
            "vx_mps,vy_mps,omega_radps,Fx_N,Mz_Nm,T [degC]\n"
            "1,0,10,n/a,-7.5,NA\n2,0,10,-1300,-,21\n3,0,10,NA,,22\n4,0,10,-1400,nan,-\n"));
  ASSERT_EQ(d.points.size(), 4u);
  EXPECT_FALSE(d.points[0].force[0].has_value());
  EXPECT_DOUBLE_EQ(*d.points[1].force[0], -1300.0);
  EXPECT_FALSE(d.points[1].force[2].has_value());
  ASSERT_EQ(d.recorded.size(), 1u);  // "NA" first did not make it a text column
  EXPECT_TRUE(std::isnan(d.points[0].recorded[0]));
  EXPECT_DOUBLE_EQ(d.points[2].recorded[0], 295.15);
  ASSERT_EQ(d.missing_values.size(), 3u);
  EXPECT_EQ(d.missing_values[0], "'Fx_N' (column 4): 2 of 4 rows (NA 1, n/a 1)");
  EXPECT_EQ(d.missing_values[1], "'Mz_Nm' (column 5): 3 of 4 rows (empty 1, - 1, nan 1)");
  EXPECT_EQ(d.missing_values[2], "'T [degC]' (column 6): 2 of 4 rows (- 1, NA 1)");
  const std::string kin = error_of("vx_mps,vy_mps,omega_radps,Fx_N\n1,0,10,-5\n1,N/A,10,-5\n");
  EXPECT_NE(kin.find(":3: column 'vy_mps' (2): 'N/A', a missing value (the kinematics vx, vy, "
                     "omega must be given in every row)"),
            std::string::npos)
      << kin;
  // Text that is no spelling of a missing value is still refused in a numeric column.
  EXPECT_NE(error_of("vx_mps,vy_mps,omega_radps,Fx_N\n1,0,10,-5\n1,0,10,n.a.\n")
                .find("not a number: 'n.a.'"),
            std::string::npos);
}

// Time is "t" or "time": a capital T (a temperature, more often than not) is a recorded
// column, with or without a suffix, beside the time.
TEST(LabColumns, ACapitalTIsATemperatureNotTheTime) {
  const MeasuredData d = read_measured_csv(
      write("lab_temp.csv",
            "time,vx_mps,vy_mps,omega_radps,Fx_N,T_tread,T\n0,1,0,3,4,25,26\n0.5,1,0,3,4,27,28\n"));
  ASSERT_EQ(d.points.size(), 2u);
  ASSERT_TRUE(d.points[1].time);
  EXPECT_DOUBLE_EQ(*d.points[1].time, 0.5);
  ASSERT_EQ(d.recorded.size(), 2u);
  EXPECT_EQ(d.recorded[0].name, "T_tread");
  EXPECT_EQ(d.recorded[1].name, "T");
  EXPECT_DOUBLE_EQ(d.points[1].recorded[0], 27.0);
}
