<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1">
    <context>
        <name>@default</name>
        <message>
            <source>terrain (hillshade)</source>
            <translation>ناهمواری (سایه‌روشن)</translation>
        </message>
        <message>
            <source>nodata</source>
            <translation>بدون داده</translation>
        </message>
        <message>
            <source>Legend</source>
            <translation>راهنما</translation>
        </message>
        <message>
            <source>Hillshade</source>
            <translation>سایه‌روشن</translation>
        </message>
        <message>
            <source>not used (outside / nodata)</source>
            <translation>به‌کارنرفته (بیرون / بدون داده)</translation>
        </message>
        <message>
            <source>Error DTM − check (m)</source>
            <translation>خطا = مدل − نقطهٔ کنترل (متر)</translation>
        </message>
        <message>
            <source>Residual map</source>
            <translation>نقشهٔ باقیمانده‌ها</translation>
        </message>
        <message>
            <source>check height (m)</source>
            <translation>ارتفاع نقطهٔ کنترل (متر)</translation>
        </message>
        <message>
            <source>error DTM − check (m)</source>
            <translation>خطا = مدل − نقطهٔ کنترل (متر)</translation>
        </message>
        <message>
            <source>zero error</source>
            <translation>خطای صفر</translation>
        </message>
        <message>
            <source>Error against height</source>
            <translation>خطا در برابر ارتفاع</translation>
        </message>
        <message>
            <source>no point</source>
            <translation>بدون نقطه</translation>
        </message>
        <message>
            <source>Class map</source>
            <translation>نقشهٔ کلاس‌ها</translation>
        </message>
        <message>
            <source>ASPRS class</source>
            <translation>کلاس ASPRS</translation>
        </message>
        <message>
            <source>Error map</source>
            <translation>نقشهٔ خطاها</translation>
        </message>
        <message>
            <source>Filter error</source>
            <translation>خطای فیلتر</translation>
        </message>
        <message>
            <source>Tile map</source>
            <translation>نقشهٔ کاشی‌ها</translation>
        </message>
        <message>
            <source>Tile status</source>
            <translation>وضعیت کاشی</translation>
        </message>
        <message>
            <source>Slope threshold θ (degrees)</source>
            <translation>آستانهٔ شیب θ (درجه)</translation>
        </message>
        <message>
            <source>Percent (%)</source>
            <translation>درصد (%)</translation>
        </message>
        <message>
            <source>best threshold</source>
            <translation>بهترین آستانه</translation>
        </message>
        <message>
            <source>Errors against the slope threshold</source>
            <translation>خطاها در برابر آستانهٔ شیب</translation>
        </message>
        <message>
            <source>fast</source>
            <translation>سریع</translation>
        </message>
        <message>
            <source>slow</source>
            <translation>کند</translation>
        </message>
        <message>
            <source>finished earlier</source>
            <translation>پیش‌تر تمام‌شده</translation>
        </message>
        <message>
            <source>failed</source>
            <translation>ناموفق</translation>
        </message>
        <message>
            <source>check-point RMS_T</source>
            <translation>RMS_T نقاط چک</translation>
        </message>
        <message>
            <source>map X</source>
            <translation>X نقشه</translation>
        </message>
        <message>
            <source>map Y</source>
            <translation>Y نقشه</translation>
        </message>
    </context>
    <context>
        <name>BuildingsAlgorithm</name>
        <message>
            <source>Building footprints with heights</source>
            <translation>ردپای ساختمان‌ها با ارتفاع</translation>
        </message>
        <message>
            <source>Roof planes found by region growing above the DTM, as footprints with height, area, volume, storeys and roof type.</source>
            <translation>صفحه‌های بام یافته‌شده با رشد ناحیه بالای مدل رقومی زمین، به‌صورت ردپا با ارتفاع، مساحت، حجم، طبقه‌ها و نوع بام.</translation>
        </message>
        <message>
            <source>buildings,footprints,roofs,lod1,extraction,height,volume,storeys,class 6,lidar</source>
            <translation>ساختمان‌ها,ردپا,بام‌ها,lod1,استخراج,ارتفاع,حجم,طبقه‌ها,کلاس ۶,لیدار</translation>
        </message>
        <message>
            <source>&lt;p&gt;Extracts buildings from a ground-classified LAS/LAZ cloud: points more than the minimum height above a TIN of the ground points are fitted with local planes; neighbours whose normals agree within the maximum angle grow into roof patches; patches of at least the minimum patch area become footprints with height (top of roof − ground at the outline), area, volume, storeys (height / 3 m) and roof type (flat / pitched). Trees are rejected because their points are not planar.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=ground_filtered.laz MIN_HEIGHT=2 MAX_ANGLE=20 OUTPUT=buildings.gpkg OUTPUT_CLOUD=classified.laz.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las/.laz with ground in class 2 (run a ground filter first), projected CRS in metres.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground classes&lt;/b&gt; (GROUND_CLASSES, default &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum height&lt;/b&gt; (MIN_HEIGHT, m, default 2; the spec gives 1.5–2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Maximum normal angle&lt;/b&gt; (MAX_ANGLE, degrees, default 20).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum roof patch area&lt;/b&gt; (MIN_PATCH_AREA, m², default 15).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum building area&lt;/b&gt; (MIN_AREA, m², default 15).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell size&lt;/b&gt; (CELL_SIZE, m, default 0.5): footprint raster.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Footprints&lt;/b&gt; (OUTPUT, GeoPackage polygons): id, height_m, area_m2, volume_m3, storeys, roof_type, ground_z, roof_z.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classified cloud&lt;/b&gt; (OUTPUT_CLOUD, optional LAS/LAZ): the input with roof points set to class 6, every other attribute kept.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: N_BUILDINGS, TOTAL_AREA (m²), TOTAL_VOLUME (m³).&lt;/p&gt;</source>
            <translation>&lt;p&gt;ساختمان‌ها را از ابر LAS/LAZ با زمین طبقه‌بندی‌شده استخراج می‌کند: به نقاطی که بیش از کمینهٔ ارتفاع بالای TIN نقاط زمین‌اند صفحه‌های محلی برازش داده می‌شود؛ نقاط همسایه‌ای که بردار عمودشان در حد بیشینهٔ زاویه هم‌جهت است به وصله‌های بام رشد می‌کنند؛ وصله‌هایی که دست‌کم کمینهٔ مساحت را دارند ردپا می‌شوند با ارتفاع (بالای بام − زمین کنار دیوار)، مساحت، حجم، طبقه‌ها (ارتفاع / ۳ متر) و نوع بام (تخت / شیب‌دار). درختان کنار گذاشته می‌شوند چون نقاطشان صفحه‌ای نیست.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=ground_filtered.laz MIN_HEIGHT=2 MAX_ANGLE=20 OUTPUT=buildings.gpkg OUTPUT_CLOUD=classified.laz.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;ابر نقاط&lt;/b&gt; (INPUT): فایل ‎.las/.laz با زمین در کلاس ۲ (نخست یک فیلتر زمین اجرا کنید)، در سیستم تصویر مسطح بر حسب متر.&lt;/li&gt;&lt;li&gt;&lt;b&gt;کلاس‌های زمین&lt;/b&gt; (GROUND_CLASSES، پیش‌فرض &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;کمینهٔ ارتفاع&lt;/b&gt; (MIN_HEIGHT، متر، پیش‌فرض ۲؛ مشخصات ۱٫۵ تا ۲ را می‌دهد).&lt;/li&gt;&lt;li&gt;&lt;b&gt;بیشینهٔ زاویهٔ بردار عمود&lt;/b&gt; (MAX_ANGLE، درجه، پیش‌فرض ۲۰).&lt;/li&gt;&lt;li&gt;&lt;b&gt;کمینهٔ مساحت وصلهٔ بام&lt;/b&gt; (MIN_PATCH_AREA، مترمربع، پیش‌فرض ۱۵).&lt;/li&gt;&lt;li&gt;&lt;b&gt;کمینهٔ مساحت ساختمان&lt;/b&gt; (MIN_AREA، مترمربع، پیش‌فرض ۱۵).&lt;/li&gt;&lt;li&gt;&lt;b&gt;اندازهٔ سلول&lt;/b&gt; (CELL_SIZE، متر، پیش‌فرض ۰٫۵): رستر ردپا.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ردپاها&lt;/b&gt; (OUTPUT، چندضلعی GeoPackage): id، height_m، area_m2، volume_m3، storeys، roof_type، ground_z، roof_z.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ابر طبقه‌بندی‌شده&lt;/b&gt; (OUTPUT_CLOUD، LAS/LAZ اختیاری): ورودی با نقاط بام در کلاس ۶ و همهٔ ویژگی‌های دیگر دست‌نخورده.&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML، اختیاری).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;اعداد خروجی: N_BUILDINGS، TOTAL_AREA (مترمربع)، TOTAL_VOLUME (مترمکعب).&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Ground classes</source>
            <translation>کلاس‌های زمین</translation>
        </message>
        <message>
            <source>Minimum height above ground (m)</source>
            <translation>کمینهٔ ارتفاع از زمین (متر)</translation>
        </message>
        <message>
            <source>Maximum angle between roof normals (°)</source>
            <translation>بیشینهٔ زاویهٔ میان بردارهای عمود بام (درجه)</translation>
        </message>
        <message>
            <source>Minimum roof patch area (m²)</source>
            <translation>کمینهٔ مساحت وصلهٔ بام (مترمربع)</translation>
        </message>
        <message>
            <source>Minimum building area (m²)</source>
            <translation>کمینهٔ مساحت ساختمان (مترمربع)</translation>
        </message>
        <message>
            <source>Cell size (m)</source>
            <translation>اندازهٔ سلول (متر)</translation>
        </message>
        <message>
            <source>Building footprints</source>
            <translation>ردپای ساختمان‌ها</translation>
        </message>
        <message>
            <source>Classified cloud (class 6 = building)</source>
            <translation>ابر طبقه‌بندی‌شده (کلاس ۶ = ساختمان)</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
    </context>
    <context>
        <name>CatalogAlgorithm</name>
        <message>
            <source>Process a LiDAR tile catalog</source>
            <translation>پردازش کاتالوگ کاشی‌های لیدار</translation>
        </message>
        <message>
            <source>Ground filter and DTM over a whole folder of LAS/LAZ tiles, in parallel, without seams.</source>
            <translation>فیلتر زمین و مدل رقومی زمین برای یک پوشهٔ کامل از کاشی‌های LAS/LAZ، به‌صورت موازی و بدون درز.</translation>
        </message>
        <message>
            <source>Keep the classes already in the files</source>
            <translation>نگه‌داشتن کلاس‌های موجود در فایل‌ها</translation>
        </message>
        <message>
            <source>LSQ surfaces, faithful (the paper)</source>
            <translation>سطوح کمترین مربعات، وفادار (مقاله)</translation>
        </message>
        <message>
            <source>LSQ surfaces, improved (ours)</source>
            <translation>سطوح کمترین مربعات، بهبودیافته (نسخهٔ ما)</translation>
        </message>
        <message>
            <source>Slope filter, exact (Vosselman 2000)</source>
            <translation>فیلتر شیب، دقیق (Vosselman 2000)</translation>
        </message>
        <message>
            <source>Slope filter, terrain-adaptive</source>
            <translation>فیلتر شیب، سازگار با عوارض زمین</translation>
        </message>
        <message>
            <source>IDW</source>
            <translation>IDW</translation>
        </message>
        <message>
            <source>Kriging</source>
            <translation>کریجینگ</translation>
        </message>
        <message>
            <source>TIN</source>
            <translation>TIN</translation>
        </message>
        <message>
            <source>&lt;p&gt;Classifies ground and builds a DTM for every tile of a LiDAR project, each tile read with a buffer of points from its neighbours so that results have no seams at tile edges; tiles run in parallel on Dask, locally or on a cluster. Example: INPUT = a folder of 1 km LAZ tiles, BUFFER = 100 m, CELL_SIZE = 1 m gives classified tiles, one DTM GeoTIFF per tile and a VRT mosaic.&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Tiles&lt;/b&gt; (INPUT): a folder of .las/.laz files, a .vpc virtual point cloud, or files separated by ';'. All tiles must share one CRS.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground filter&lt;/b&gt; (GROUND_FILTER, default the recommended one): 0 keeps the classes already in the files.&lt;/li&gt;&lt;li&gt;&lt;b&gt;DTM method&lt;/b&gt; (DTM_METHOD, default IDW) and &lt;b&gt;cell size&lt;/b&gt; (CELL_SIZE, m, default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Buffer&lt;/b&gt; (BUFFER, m, default 100): must exceed the filter's reach (LSQ tile size × 2, slope radius) and the DTM search distance.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Workers&lt;/b&gt; (WORKERS, default 0 = one per core) and &lt;b&gt;Dask scheduler&lt;/b&gt; (SCHEDULER, e.g. tcp://host:8786; empty = a local cluster).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Output folder&lt;/b&gt; (OUTPUT_FOLDER; must not hold the input tiles): &amp;lt;tile&amp;gt;_classified, &amp;lt;tile&amp;gt;_dtm.tif, dtm.vrt, optionally one Cloud-Optimized GeoTIFF (COG), and the HTML report (OUTPUT_HTML) with a map of the tiles by status and time and points per second per worker. A rerun skips finished tiles; cancel keeps finished tiles.&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;p&gt;نقاط زمین را طبقه‌بندی می‌کند و برای هر کاشی یک پروژهٔ لیدار مدل رقومی زمین می‌سازد؛ هر کاشی همراه با حاشیه‌ای از نقاط همسایگانش خوانده می‌شود تا در لبهٔ کاشی‌ها درزی نماند؛ کاشی‌ها به‌صورت موازی روی Dask، محلی یا روی یک خوشه، پردازش می‌شوند. مثال: INPUT = پوشه‌ای از کاشی‌های LAZ یک‌کیلومتری، BUFFER = ۱۰۰ متر، CELL_SIZE = ۱ متر، کاشی‌های طبقه‌بندی‌شده، یک GeoTIFF مدل زمین برای هر کاشی و یک موزاییک VRT می‌دهد.&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;کاشی‌ها&lt;/b&gt; (INPUT): پوشه‌ای از فایل‌های ‎.las/.laz، یک ابر نقاط مجازی ‎.vpc یا فایل‌هایی جداشده با ';'. همهٔ کاشی‌ها باید یک سیستم مختصات داشته باشند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;فیلتر زمین&lt;/b&gt; (GROUND_FILTER، پیش‌فرض: فیلتر توصیه‌شده): 0 کلاس‌های موجود در فایل‌ها را نگه می‌دارد.&lt;/li&gt;&lt;li&gt;&lt;b&gt;روش مدل زمین&lt;/b&gt; (DTM_METHOD، پیش‌فرض IDW) و &lt;b&gt;اندازهٔ سلول&lt;/b&gt; (CELL_SIZE، متر، پیش‌فرض ۱).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حاشیه&lt;/b&gt; (BUFFER، متر، پیش‌فرض ۱۰۰): باید از برد فیلتر (دو برابر اندازهٔ کاشی کمترین مربعات، شعاع شیب) و فاصلهٔ جست‌وجوی مدل بیشتر باشد.&lt;/li&gt;&lt;li&gt;&lt;b&gt;پردازه‌های کارگر&lt;/b&gt; (WORKERS، پیش‌فرض 0 = یکی برای هر هسته) و &lt;b&gt;زمان‌بند Dask&lt;/b&gt; (SCHEDULER، مثلاً tcp://host:8786؛ خالی = خوشهٔ محلی).&lt;/li&gt;&lt;li&gt;&lt;b&gt;پوشهٔ خروجی&lt;/b&gt; (OUTPUT_FOLDER؛ نباید کاشی‌های ورودی را در خود داشته باشد): &amp;lt;tile&amp;gt;_classified، &amp;lt;tile&amp;gt;_dtm.tif، dtm.vrt، در صورت نیاز یک GeoTIFF بهینه برای ابر (COG) و گزارش HTML ‏(OUTPUT_HTML) با نقشهٔ کاشی‌ها بر پایهٔ وضعیت و زمان و تعداد نقطه در ثانیه برای هر کارگر. اجرای دوباره کاشی‌های تمام‌شده را رد می‌کند؛ لغو، کاشی‌های تمام‌شده را نگه می‌دارد.&lt;/li&gt;&lt;/ul&gt;</translation>
        </message>
        <message>
            <source>Tiles: folder, .vpc or files separated by ';'</source>
            <translation>کاشی‌ها: پوشه، ‎.vpc یا فایل‌های جداشده با ';'</translation>
        </message>
        <message>
            <source>Ground filter</source>
            <translation>فیلتر زمین</translation>
        </message>
        <message>
            <source>DTM method</source>
            <translation>روش مدل رقومی زمین</translation>
        </message>
        <message>
            <source>DTM cell size (m)</source>
            <translation>اندازهٔ سلول مدل زمین (متر)</translation>
        </message>
        <message>
            <source>Buffer around each tile (m)</source>
            <translation>حاشیهٔ پیرامون هر کاشی (متر)</translation>
        </message>
        <message>
            <source>Worker processes (0 = one per core)</source>
            <translation>پردازه‌های کارگر (0 = یکی برای هر هسته)</translation>
        </message>
        <message>
            <source>Dask scheduler address (empty = local)</source>
            <translation>نشانی زمان‌بند Dask (خالی = محلی)</translation>
        </message>
        <message>
            <source>Also write one Cloud-Optimized GeoTIFF</source>
            <translation>نوشتن یک GeoTIFF بهینه برای ابر نیز</translation>
        </message>
        <message>
            <source>Output folder</source>
            <translation>پوشهٔ خروجی</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>Tiles</source>
            <translation>کاشی‌ها</translation>
        </message>
        <message>
            <source>Failed tiles</source>
            <translation>کاشی‌های ناموفق</translation>
        </message>
        <message>
            <source>Points per second</source>
            <translation>نقطه در ثانیه</translation>
        </message>
        <message>
            <source>Tile {0} failed: {1}</source>
            <translation>کاشی {0} ناموفق بود: {1}</translation>
        </message>
        <message>
            <source>Ground filter (recommended)</source>
            <translation>فیلتر زمین (پیشنهادی)</translation>
        </message>
    </context>
    <context>
        <name>DsmAlgorithm</name>
        <message>
            <source>DSM and nDSM / canopy height model</source>
            <translation>مدل رقومی سطح (DSM) و nDSM / مدل ارتفاع تاج پوشش گیاهی</translation>
        </message>
        <message>
            <source>dsm,ndsm,chm,canopy height,surface model,first returns,lidar,raster</source>
            <translation>dsm,ndsm,chm,ارتفاع تاج پوشش,مدل سطح,بازگشت‌های اول,لایدار,رستر</translation>
        </message>
        <message>
            <source>&lt;p&gt;Digital surface model from a LAS/LAZ file: every cell takes the highest return falling in it (first returns only as an option, the usual canopy surface). With a DTM, also the normalised DSM (nDSM; canopy height model in forests) = DSM − DTM on the DTM's grid. Points are read in chunks, so large files fit in memory.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=cloud.laz CELL_SIZE=1 FIRST_RETURNS=true DTM=dtm.tif OUTPUT=dsm.tif OUTPUT_NDSM=chm.tif.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las/.laz.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classes used&lt;/b&gt; (CLASSES, default empty = all classes).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Excluded classes&lt;/b&gt; (EXCLUDE_CLASSES, default &lt;code&gt;7,18&lt;/code&gt;: low and high noise).&lt;/li&gt;&lt;li&gt;&lt;b&gt;First returns only&lt;/b&gt; (FIRST_RETURNS, default no).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell size&lt;/b&gt; (CELL_SIZE, m, default 1), &lt;b&gt;Extent&lt;/b&gt; (EXTENT), &lt;b&gt;CRS&lt;/b&gt; (CRS): as for the DTM tools; ignored when a DTM is given (its grid and CRS are used so that DSM and DTM align cell for cell).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Fill distance&lt;/b&gt; (FILL_DISTANCE, m, default 0): empty cells take the value of the nearest non-empty cell within this distance; 0 = leave them nodata.&lt;/li&gt;&lt;li&gt;&lt;b&gt;DTM&lt;/b&gt; (DTM, optional raster): needed for the nDSM.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Clamp negative heights to 0&lt;/b&gt; (CLAMP_NEGATIVE, default yes).&lt;/li&gt;&lt;li&gt;&lt;b&gt;DSM&lt;/b&gt; (OUTPUT) and &lt;b&gt;nDSM&lt;/b&gt; (OUTPUT_NDSM, optional, needs DTM): GeoTIFF, nodata −9999.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional).&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;p&gt;مدل رقومی سطح از یک پروندهٔ LAS/LAZ: هر سلول بالاترین بازگشتی را که در آن می‌افتد می‌گیرد (به‌اختیار فقط بازگشت‌های اول، که سطح معمول تاج پوشش گیاهی است). با داشتن مدل رقومی زمین (DTM)، مدل رقومی سطح نرمال‌شده (nDSM؛ در جنگل همان مدل ارتفاع تاج پوشش) = DSM − DTM نیز روی شبکهٔ DTM ساخته می‌شود. نقاط تکه‌تکه خوانده می‌شوند، پس پرونده‌های بزرگ هم در حافظه جا می‌گیرند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=cloud.laz CELL_SIZE=1 FIRST_RETURNS=true DTM=dtm.tif OUTPUT=dsm.tif OUTPUT_NDSM=chm.tif.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;ابر نقاط&lt;/b&gt; (INPUT): پروندهٔ .las/.laz.&lt;/li&gt;&lt;li&gt;&lt;b&gt;کلاس‌های به‌کاررفته&lt;/b&gt; (CLASSES، پیش‌فرض خالی = همهٔ کلاس‌ها).&lt;/li&gt;&lt;li&gt;&lt;b&gt;کلاس‌های کنارگذاشته&lt;/b&gt; (EXCLUDE_CLASSES، پیش‌فرض &lt;code&gt;7,18&lt;/code&gt;: نویز پایین و بالا).&lt;/li&gt;&lt;li&gt;&lt;b&gt;فقط بازگشت‌های اول&lt;/b&gt; (FIRST_RETURNS، پیش‌فرض: خیر).&lt;/li&gt;&lt;li&gt;&lt;b&gt;اندازهٔ سلول&lt;/b&gt; (CELL_SIZE، متر، پیش‌فرض 1)، &lt;b&gt;محدوده&lt;/b&gt; (EXTENT)، &lt;b&gt;سیستم مختصات&lt;/b&gt; (CRS): مانند ابزارهای مدل رقومی زمین؛ وقتی DTM داده شود نادیده گرفته می‌شوند (شبکه و سیستم مختصات آن به کار می‌رود تا DSM و DTM سلول‌به‌سلول بر هم منطبق باشند).&lt;/li&gt;&lt;li&gt;&lt;b&gt;فاصلهٔ پر کردن&lt;/b&gt; (FILL_DISTANCE، متر، پیش‌فرض 0): سلول‌های خالی مقدار نزدیک‌ترین سلول غیرخالی در این فاصله را می‌گیرند؛ 0 = nodata می‌مانند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;مدل رقومی زمین&lt;/b&gt; (DTM، رستر اختیاری): برای nDSM لازم است.&lt;/li&gt;&lt;li&gt;&lt;b&gt;برابر 0 قرار دادن ارتفاع‌های منفی&lt;/b&gt; (CLAMP_NEGATIVE، پیش‌فرض: بله).&lt;/li&gt;&lt;li&gt;&lt;b&gt;DSM&lt;/b&gt; (OUTPUT) و &lt;b&gt;nDSM&lt;/b&gt; (OUTPUT_NDSM، اختیاری، نیازمند DTM): GeoTIFF، با nodata برابر −9999.&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML، اختیاری).&lt;/li&gt;&lt;/ul&gt;</translation>
        </message>
        <message>
            <source>Excluded classes</source>
            <translation>کلاس‌های کنارگذاشته</translation>
        </message>
        <message>
            <source>First returns only</source>
            <translation>فقط بازگشت‌های اول</translation>
        </message>
        <message>
            <source>Fill empty cells up to (m)</source>
            <translation>پر کردن سلول‌های خالی تا فاصلهٔ (متر)</translation>
        </message>
        <message>
            <source>DTM (for the nDSM; its grid is used)</source>
            <translation>مدل رقومی زمین DTM (برای nDSM؛ شبکهٔ آن به کار می‌رود)</translation>
        </message>
        <message>
            <source>Clamp negative nDSM heights to 0</source>
            <translation>برابر 0 قرار دادن ارتفاع‌های منفی nDSM</translation>
        </message>
        <message>
            <source>DSM</source>
            <translation>مدل رقومی سطح (DSM)</translation>
        </message>
        <message>
            <source>nDSM / canopy height model</source>
            <translation>nDSM / مدل ارتفاع تاج پوشش گیاهی</translation>
        </message>
        <message>
            <source>The point cloud CRS ({}) differs from the DTM CRS ({}); give a DTM in the point cloud's CRS. No output was written.</source>
            <translation>سیستم مختصات ابر نقاط ({}) با سیستم مختصات مدل رقومی زمین ({}) متفاوت است؛ مدل رقومی زمینی در سیستم مختصات ابر نقاط بدهید. هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>The nDSM needs a DTM: give the DTM parameter (e.g. the output of the IDW DTM algorithm). No output was written.</source>
            <translation>nDSM به مدل رقومی زمین نیاز دارد: پارامتر DTM را بدهید (مثلاً خروجی الگوریتم مدل رقومی زمین به روش IDW). هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
    </context>
    <context>
        <name>DtmAccuracyAlgorithm</name>
        <message>
            <source>DTM accuracy against check points</source>
            <translation>دقت مدل رقومی زمین نسبت به نقاط چک</translation>
        </message>
        <message>
            <source>dtm,dem,accuracy,rmse,check points,gnss,nmad,asprs,vertical accuracy,validation</source>
            <translation>dtm,dem,دقت,rmse,نقاط چک,gnss,nmad,asprs,دقت ارتفاعی,اعتبارسنجی</translation>
        </message>
        <message>
            <source>&lt;p&gt;Compares a DTM with independent check points (e.g. GNSS heights). The DTM is sampled at each point (bilinear by default) and the errors e = z&lt;sub&gt;DTM&lt;/sub&gt; − z&lt;sub&gt;check&lt;/sub&gt; are summarised: N, mean error (bias), MAE, RMSE, standard deviation, max |e|, Pearson r and R² (= r²) between DTM and check heights, NMAD = 1.4826·median|e − median e| (Höhle &amp;amp; Höhle 2009), and the vertical accuracy at 95 % confidence = 1.96·RMSE (ASPRS Positional Accuracy Standards 2014, which assumes unbiased normal errors; the 95th percentile of |e| is reported too). Check points outside the DTM or on nodata are counted and excluded — never read as 0.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: DTM=dtm.tif CHECKPOINTS_CSV=gnss.csv → RMSE, r and a report with a scatter plot and an error histogram.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;DTM&lt;/b&gt; (DTM): raster layer; BAND (default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Check points&lt;/b&gt; (CHECKPOINTS, optional): point layer; heights from &lt;b&gt;Z_FIELD&lt;/b&gt; or, if empty, from the geometry Z. &lt;b&gt;ID_FIELD&lt;/b&gt; optional.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Check point file&lt;/b&gt; (CHECKPOINTS_CSV, optional): delimited text with a header x/easting, y/northing, z/height (and id/name), or columns id x y z without header. Give the layer or the file.&lt;/li&gt;&lt;li&gt;&lt;b&gt;CSV CRS&lt;/b&gt; (CSV_CRS, optional): CRS of the file's coordinates; default = the DTM's CRS.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Reproject check points&lt;/b&gt; (REPROJECT, default no): when the check points are in another CRS than the DTM, transform them (x, y only — heights are not converted between vertical datums). Without it such points are an error.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Sampling&lt;/b&gt; (METHOD, 0 bilinear (default), 1 nearest cell).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Residuals&lt;/b&gt; (OUTPUT): point layer with id, z_check, z_dtm, error, abs_error and status (used / outside DTM / DTM nodata).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML): HTML with the statistics, a DTM vs check scatter plot, an error histogram and the residual table.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Every statistic is also an output number (N, N_OUTSIDE, N_NODATA, ME, MAE, RMSE, STD, MAX_ABS_ERROR, R, R2, NMAD, ACCURACY_95).&lt;/p&gt;</source>
            <translation>&lt;p&gt;مدل رقومی زمین (DTM) را با نقاط چک مستقل (مثلاً ارتفاع‌های GNSS) مقایسه می‌کند. مدل در محل هر نقطه نمونه‌برداری می‌شود (به‌طور پیش‌فرض دوخطی) و خطاهای e = z&lt;sub&gt;DTM&lt;/sub&gt; − z&lt;sub&gt;check&lt;/sub&gt; خلاصه می‌شوند: تعداد N، میانگین خطا (اریبی)، میانگین قدرمطلق خطا MAE، جذر میانگین مربعات خطا RMSE، انحراف معیار، بیشینهٔ |e|، ضریب همبستگی پیرسون r و R² (= r²) میان ارتفاع‌های مدل و نقاط چک، NMAD = 1.4826·median|e − median e| (Höhle &amp; Höhle 2009)، و دقت ارتفاعی در سطح اطمینان 95 % = 1.96·RMSE (استاندارد دقت موقعیتی ASPRS 2014، که خطاهای نرمال بدون اریبی را فرض می‌کند؛ صدک 95 درصدی |e| نیز گزارش می‌شود). نقاط چکی که بیرون از مدل یا روی nodata باشند شمرده و کنار گذاشته می‌شوند — هرگز 0 خوانده نمی‌شوند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: DTM=dtm.tif CHECKPOINTS_CSV=gnss.csv ← RMSE، r و گزارشی با نمودار پراکنش و هیستوگرام خطا.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;مدل رقومی زمین&lt;/b&gt; (DTM): لایهٔ رستری؛ BAND (پیش‌فرض 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;نقاط چک&lt;/b&gt; (CHECKPOINTS، اختیاری): لایهٔ نقطه‌ای؛ ارتفاع‌ها از &lt;b&gt;Z_FIELD&lt;/b&gt; یا، اگر خالی باشد، از Z هندسه. &lt;b&gt;ID_FIELD&lt;/b&gt; اختیاری است.&lt;/li&gt;&lt;li&gt;&lt;b&gt;پروندهٔ نقاط چک&lt;/b&gt; (CHECKPOINTS_CSV، اختیاری): متن جداشده با سرستون‌های x/easting، y/northing، z/height (و id/name)، یا ستون‌های id x y z بدون سرستون. لایه یا پرونده را بدهید.&lt;/li&gt;&lt;li&gt;&lt;b&gt;سیستم مختصات CSV&lt;/b&gt; (CSV_CRS، اختیاری): سیستم مختصاتِ مختصات پرونده؛ پیش‌فرض = سیستم مختصات DTM.&lt;/li&gt;&lt;li&gt;&lt;b&gt;بازتصویر نقاط چک&lt;/b&gt; (REPROJECT، پیش‌فرض: خیر): وقتی نقاط چک در سیستم مختصاتی غیر از DTM باشند، به آن تبدیل می‌شوند (فقط x و y — ارتفاع‌ها میان دیتوم‌های ارتفاعی تبدیل نمی‌شوند). بدون این گزینه، چنین نقاطی خطا به شمار می‌آیند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;روش نمونه‌برداری&lt;/b&gt; (METHOD، 0 دوخطی (پیش‌فرض)، 1 نزدیک‌ترین سلول).&lt;/li&gt;&lt;li&gt;&lt;b&gt;باقی‌مانده‌ها&lt;/b&gt; (OUTPUT): لایهٔ نقطه‌ای با id، z_check، z_dtm، error، abs_error و status (used / outside DTM / DTM nodata).&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML): HTML با آماره‌ها، نمودار پراکنش DTM در برابر نقاط چک، هیستوگرام خطا و جدول باقی‌مانده‌ها.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;هر آماره یک خروجی عددی نیز هست (N، N_OUTSIDE، N_NODATA، ME، MAE، RMSE، STD، MAX_ABS_ERROR، R، R2، NMAD، ACCURACY_95).&lt;/p&gt;</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>مدل رقومی زمین (DTM)</translation>
        </message>
        <message>
            <source>Band</source>
            <translation>باند</translation>
        </message>
        <message>
            <source>Check points (point layer)</source>
            <translation>نقاط چک (لایهٔ نقطه‌ای)</translation>
        </message>
        <message>
            <source>Height field (empty = geometry Z)</source>
            <translation>فیلد ارتفاع (خالی = Z هندسه)</translation>
        </message>
        <message>
            <source>Id field</source>
            <translation>فیلد شناسه</translation>
        </message>
        <message>
            <source>Check point file (CSV/TXT)</source>
            <translation>پروندهٔ نقاط چک (CSV/TXT)</translation>
        </message>
        <message>
            <source>CRS of the check point file (default: DTM CRS)</source>
            <translation>سیستم مختصات پروندهٔ نقاط چک (پیش‌فرض: سیستم مختصات DTM)</translation>
        </message>
        <message>
            <source>Reproject check points to the DTM CRS</source>
            <translation>بازتصویر نقاط چک به سیستم مختصات DTM</translation>
        </message>
        <message>
            <source>Sampling</source>
            <translation>روش نمونه‌برداری</translation>
        </message>
        <message>
            <source>Bilinear</source>
            <translation>دوخطی</translation>
        </message>
        <message>
            <source>Nearest cell</source>
            <translation>نزدیک‌ترین سلول</translation>
        </message>
        <message>
            <source>Residuals</source>
            <translation>باقی‌مانده‌ها</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>Give the check points as a point layer (CHECKPOINTS) or a file (CHECKPOINTS_CSV).</source>
            <translation>نقاط چک را به‌صورت لایهٔ نقطه‌ای (CHECKPOINTS) یا پرونده (CHECKPOINTS_CSV) بدهید.</translation>
        </message>
        <message>
            <source>Give the check points either as a layer or as a file, not both.</source>
            <translation>نقاط چک را یا به‌صورت لایه یا به‌صورت پرونده بدهید، نه هر دو.</translation>
        </message>
        <message>
            <source>The check point layer has no Z coordinate; choose the height field (Z_FIELD).</source>
            <translation>لایهٔ نقاط چک مختصات Z ندارد؛ فیلد ارتفاع (Z_FIELD) را انتخاب کنید.</translation>
        </message>
        <message>
            <source>The check point layer has no points.</source>
            <translation>لایهٔ نقاط چک هیچ نقطه‌ای ندارد.</translation>
        </message>
        <message>
            <source>check point layer</source>
            <translation>لایهٔ نقاط چک</translation>
        </message>
        <message>
            <source>check point file</source>
            <translation>پروندهٔ نقاط چک</translation>
        </message>
        <message>
            <source>The {} is in {} but the DTM is in {}. Reproject the check points first or tick 'Reproject check points to the DTM CRS' (REPROJECT=true; x, y only, heights are not converted). No output was written.</source>
            <translation>{} در سیستم مختصات {} است ولی مدل رقومی زمین در {} است. ابتدا نقاط چک را بازتصویر کنید یا گزینهٔ 'بازتصویر نقاط چک به سیستم مختصات DTM' را فعال کنید (REPROJECT=true؛ فقط x و y، ارتفاع‌ها تبدیل نمی‌شوند). هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Check points reprojected from {} to {}</source>
            <translation>نقاط چک از {} به {} بازتصویر شدند</translation>
        </message>
        <message>
            <source>Check points assumed to be in the DTM's CRS.</source>
            <translation>فرض شد نقاط چک در سیستم مختصات مدل رقومی زمین هستند.</translation>
        </message>
        <message>
            <source>Choose a DTM raster.</source>
            <translation>یک رستر مدل رقومی زمین انتخاب کنید.</translation>
        </message>
        <message>
            <source>N = {}, RMSE = {:.4f} m, ME = {:.4f} m, r = {:.5f}; {} outside, {} on nodata</source>
            <translation>N = {}، RMSE = {:.4f} متر، ME = {:.4f} متر، r = {:.5f}؛ {} بیرون از مدل، {} روی nodata</translation>
        </message>
    </context>
    <context>
        <name>ElevationChangeAlgorithm</name>
        <message>
            <source>Elevation change between two epochs (cut / fill)</source>
            <translation>تغییر ارتفاع میان دو دوره (خاک‌برداری / خاک‌ریزی)</translation>
        </message>
        <message>
            <source>Difference of two surveys with a 95 % level of detection, and cut and fill polygons with volumes.</source>
            <translation>تفاضل دو برداشت با حد آشکارسازی ۹۵ درصد، و چندضلعی‌های خاک‌برداری و خاک‌ریزی با حجم آن‌ها.</translation>
        </message>
        <message>
            <source>change,difference,dod,cut,fill,volume,epochs,lod,monitoring,lidar,dtm,dsm</source>
            <translation>تغییر,تفاضل,dod,خاک‌برداری,خاک‌ریزی,حجم,دوره‌ها,حد آشکارسازی,پایش,لیدار,dtm,dsm</translation>
        </message>
        <message>
            <source>&lt;p&gt;Subtracts an earlier surface from a later one (two DTM/DSM rasters on one grid, or two LAS/LAZ clouds gridded by TIN on a common grid) and keeps the change beyond the level of detection LoD95 = 1.96·√(σ₁² + σ₂²), σ being each epoch's vertical accuracy (e.g. the RMSE of the DTM accuracy tool). Significant cells form cut and fill polygons with area, mean change and volume.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=dtm_2021.tif INPUT_AFTER=dtm_2024.tif SIGMA1=0.08 SIGMA2=0.06.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Before&lt;/b&gt; (INPUT) and &lt;b&gt;After&lt;/b&gt; (INPUT_AFTER): two GeoTIFFs on the same grid, or two LAS/LAZ clouds in one CRS.&lt;/li&gt;&lt;li&gt;&lt;b&gt;σ₁, σ₂&lt;/b&gt; (SIGMA1, SIGMA2, m, default 0.1): vertical accuracy of each epoch.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classes&lt;/b&gt; (CLASSES, clouds only, default &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell size&lt;/b&gt; (CELL_SIZE, m, clouds only, default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum area&lt;/b&gt; (MIN_AREA, m², default 0 = eight cells): smaller regions are dropped (noise alone exceeds the LoD in 5 % of cells).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Difference&lt;/b&gt; (OUTPUT): GeoTIFF after − before (m).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Change polygons&lt;/b&gt; (OUTPUT_POLYGONS, GeoPackage): id, kind (cut / fill), area_m2, mean_change_m, volume_m3.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: LOD, FILL_VOLUME, CUT_VOLUME (m³), N_REGIONS.&lt;/p&gt;</source>
            <translation>&lt;p&gt;سطح پیشین را از سطح پسین کم می‌کند (دو رستر DTM/DSM روی یک شبکه، یا دو ابر LAS/LAZ که با TIN روی شبکه‌ای مشترک شبکه‌بندی می‌شوند) و تغییری را نگه می‌دارد که از حد آشکارسازی LoD95 = 1.96·√(σ₁² + σ₂²) بیشتر است؛ σ دقت ارتفاعی هر دوره است (مثلاً RMSE ابزار دقت مدل رقومی زمین). سلول‌های معنادار چندضلعی‌های خاک‌برداری و خاک‌ریزی با مساحت، میانگین تغییر و حجم می‌سازند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=dtm_2021.tif INPUT_AFTER=dtm_2024.tif SIGMA1=0.08 SIGMA2=0.06.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;پیش از&lt;/b&gt; (INPUT) و &lt;b&gt;پس از&lt;/b&gt; (INPUT_AFTER): دو GeoTIFF روی یک شبکه، یا دو ابر LAS/LAZ در یک سیستم مختصات.&lt;/li&gt;&lt;li&gt;&lt;b&gt;σ₁ و σ₂&lt;/b&gt; (SIGMA1، SIGMA2، متر، پیش‌فرض 0.1): دقت ارتفاعی هر دوره.&lt;/li&gt;&lt;li&gt;&lt;b&gt;کلاس‌ها&lt;/b&gt; (CLASSES، فقط برای ابرها، پیش‌فرض &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;اندازهٔ سلول&lt;/b&gt; (CELL_SIZE، متر، فقط برای ابرها، پیش‌فرض 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;کمینهٔ مساحت&lt;/b&gt; (MIN_AREA، مترمربع، پیش‌فرض 0 = هشت سلول): نواحی کوچک‌تر حذف می‌شوند (نویز به‌تنهایی در ۵ درصد سلول‌ها از حد آشکارسازی می‌گذرد).&lt;/li&gt;&lt;li&gt;&lt;b&gt;تفاضل&lt;/b&gt; (OUTPUT): GeoTIFF پس از − پیش از (متر).&lt;/li&gt;&lt;li&gt;&lt;b&gt;چندضلعی‌های تغییر&lt;/b&gt; (OUTPUT_POLYGONS، GeoPackage): id، kind (خاک‌برداری / خاک‌ریزی)، area_m2، mean_change_m، volume_m3.&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML، اختیاری).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;اعداد خروجی: LOD، FILL_VOLUME، CUT_VOLUME (مترمکعب)، N_REGIONS.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Before (raster or point cloud)</source>
            <translation>پیش از (رستر یا ابر نقاط)</translation>
        </message>
        <message>
            <source>After (raster or point cloud)</source>
            <translation>پس از (رستر یا ابر نقاط)</translation>
        </message>
        <message>
            <source>Vertical accuracy before σ₁ (m)</source>
            <translation>دقت ارتفاعی پیش از σ₁ (متر)</translation>
        </message>
        <message>
            <source>Vertical accuracy after σ₂ (m)</source>
            <translation>دقت ارتفاعی پس از σ₂ (متر)</translation>
        </message>
        <message>
            <source>Classes used (clouds)</source>
            <translation>کلاس‌های به‌کاررفته (برای ابرها)</translation>
        </message>
        <message>
            <source>Cell size (m, clouds)</source>
            <translation>اندازهٔ سلول (متر، برای ابرها)</translation>
        </message>
        <message>
            <source>Minimum region area (m², 0 = 8 cells)</source>
            <translation>کمینهٔ مساحت ناحیه (مترمربع، 0 = هشت سلول)</translation>
        </message>
        <message>
            <source>Difference</source>
            <translation>تفاضل</translation>
        </message>
        <message>
            <source>Change polygons</source>
            <translation>چندضلعی‌های تغییر</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
    </context>
    <context>
        <name>GcpAccuracyReportAlgorithm</name>
        <message>
            <source>GCP accuracy report</source>
            <translation>گزارش دقت نقاط کنترل زمینی</translation>
        </message>
        <message>
            <source>georeference,gcp,ground control points,rms,residuals,accuracy,check points,leave-one-out,polynomial,georeferencer</source>
            <translation>زمین‌مرجع‌سازی,gcp,نقاط کنترل زمینی,rms,باقی‌مانده‌ها,دقت,نقاط چک,حذف‌یکی,چندجمله‌ای,georeferencer</translation>
        </message>
        <message>
            <source>Image width (px) if no image is given</source>
            <translation>عرض تصویر (پیکسل) اگر تصویری داده نشود</translation>
        </message>
        <message>
            <source>Image height (px) if no image is given</source>
            <translation>ارتفاع تصویر (پیکسل) اگر تصویری داده نشود</translation>
        </message>
        <message>
            <source>Accuracy report</source>
            <translation>گزارش دقت</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>Residuals table</source>
            <translation>جدول باقی‌مانده‌ها</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>پرونده‌های CSV (*.csv)</translation>
        </message>
        <message>
            <source>Report as JSON</source>
            <translation>گزارش به قالب JSON</translation>
        </message>
        <message>
            <source>JSON files (*.json)</source>
            <translation>پرونده‌های JSON (*.json)</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML), &lt;b&gt;residual table&lt;/b&gt; (OUTPUT_CSV: one row per point with v_x, v_y, RMS_i, C_i, pixel residuals, leave-one-out residuals) and &lt;b&gt;JSON&lt;/b&gt; (OUTPUT_JSON: everything, all orders), each optional.&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML)، &lt;b&gt;جدول باقی‌مانده‌ها&lt;/b&gt; (OUTPUT_CSV: یک سطر برای هر نقطه با v_x، v_y، RMS_i، C_i، باقی‌مانده‌ها به پیکسل و باقی‌مانده‌های حذف‌یکی) و &lt;b&gt;JSON&lt;/b&gt; (OUTPUT_JSON: همه‌چیز، برای همهٔ درجه‌ها)، همه اختیاری.&lt;/li&gt;&lt;/ul&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;Every summary figure is also an output number (RMS_T, RMS_T_QGIS, GR, SCALE, LOO_RMS_T, CHECK_RMS_T, RECOMMENDED_ORDER, ACCEPTED, RMS_T_ORDER1…3, …) for the graphical modeler.&lt;/p&gt;</source>
            <translation>&lt;p&gt;هر رقم خلاصهٔ نتایج یک خروجی عددی نیز هست (RMS_T، RMS_T_QGIS، GR، SCALE، LOO_RMS_T، CHECK_RMS_T، RECOMMENDED_ORDER، ACCEPTED، RMS_T_ORDER1…3، …) برای طراح گرافیکی مدل.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;Judges a set of ground control points without warping: every transformation (polynomial 1–3, linear, Helmert, projective, thin-plate spline) side by side by the paper's criteria on check points and leave-one-out residuals, with the recommended one and why.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: GCP_FILE=scan.tif.points INPUT=scan.tif TRANSFORMATION=8 GR=0.91 OUTPUT_HTML=report.html OUTPUT_CSV=residuals.csv&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Image&lt;/b&gt; (INPUT, optional): gives the image size (GCPs outside it are an error; quadrants and the plot use its footprint). Without it, give IMAGE_WIDTH and IMAGE_HEIGHT (pixels) or the GCP centroid is used.&lt;/li&gt;</source>
            <translation>&lt;p&gt;مجموعه‌ای از نقاط کنترل زمینی را بدون تصحیح تصویر داوری می‌کند: همهٔ تبدیل‌ها (چندجمله‌ای 1–3، خطی، هلمرت، تصویری، اسپلاین صفحهٔ نازک) در کنار هم با معیارهای مقاله روی نقاط چک و باقیمانده‌های حذف‌یکی، همراه با تبدیل پیشنهادی و دلیل آن.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: GCP_FILE=scan.tif.points INPUT=scan.tif TRANSFORMATION=8 GR=0.91 OUTPUT_HTML=report.html OUTPUT_CSV=residuals.csv&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;تصویر&lt;/b&gt; (INPUT، اختیاری): ابعاد تصویر را می‌دهد (نقاط کنترل بیرون از آن خطا به شمار می‌آیند؛ ربع‌ها و نمودار از محدودهٔ آن استفاده می‌کنند). بدون آن، IMAGE_WIDTH و IMAGE_HEIGHT (پیکسل) را بدهید، وگرنه مرکز ثقل نقاط کنترل به کار می‌رود.&lt;/li&gt;</translation>
        </message>
    </context>
    <context>
        <name>GeomaticsAlgorithm</name>
        <message>
            <source>LiDAR ground filtering</source>
            <translation>فیلتر کردن نقاط زمینی لایدار</translation>
        </message>
        <message>
            <source>Terrain models</source>
            <translation>مدل‌های رقومی زمین</translation>
        </message>
        <message>
            <source>Image rectification</source>
            <translation>تصحیح هندسی تصویر</translation>
        </message>
        <message>
            <source>Photogrammetry</source>
            <translation>فتوگرامتری</translation>
        </message>
        <message>
            <source>Accuracy assessment</source>
            <translation>ارزیابی دقت</translation>
        </message>
        <message>
            <source>Cancelled by the user; no output was written.</source>
            <translation>کاربر عملیات را لغو کرد؛ هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Out of memory. Use a coarser cell size, a smaller extent or fewer points; no output was written.</source>
            <translation>حافظه کافی نیست. اندازهٔ سلول بزرگ‌تر، محدودهٔ کوچک‌تر یا نقاط کمتری به کار ببرید؛ هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;GCP file&lt;/b&gt; (GCP_FILE): a QGIS Georeferencer &lt;i&gt;.points&lt;/i&gt; file (mapX,mapY,pixelX,pixelY,enable,…; pixelY is minus the row) or a CSV table with columns id, col,row (or pixel,line; or image_x,image_y in the QGIS sign convention), X,Y (or map_x,map_y / easting,northing) and optional enabled (1/0), role (gcp or check) and weight. Give the file &lt;i&gt;or&lt;/i&gt; a point layer; with neither, the Georeferencer's &lt;i&gt;&amp;lt;image&amp;gt;.points&lt;/i&gt; next to the image is used.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GCP point layer&lt;/b&gt; (GCP_LAYER): points whose geometry holds the map coordinates (in the layer CRS) with fields for the image column and row (COL_FIELD, ROW_FIELD) and optional ID_FIELD, ENABLED_FIELD, ROLE_FIELD, WEIGHT_FIELD (least-squares weights, e.g. 1/σ²; the report uses them, GDAL's warp fits unweighted).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Pixel origin&lt;/b&gt; (PIXEL_ORIGIN, default 0 = corner): 0 — image coordinates in the GDAL/QGIS convention, (0,0) is the top-left corner of the image and the centre of the first pixel is (0.5, 0.5); 1 — integer values are pixel centres (0-based array indices), 0.5 is added. Rows always grow downwards (a negative row column is read as QGIS's −row). .points files are always corner-based.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GCP CRS&lt;/b&gt; (GCP_CRS): CRS of the map coordinates when the file has no '#CRS:' line (CSV files never have one). Missing CRS is an error.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Polynomial order&lt;/b&gt; (ORDER, 1–3, default 1): 1 affine (≥ 3 GCPs), 2 (≥ 6), 3 (≥ 10).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground resolution GR&lt;/b&gt; (GR, map units per pixel, optional): pixel size on the ground for the criteria; default sqrt|det J| of the affine fit of the GCPs.&lt;/li&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;پروندهٔ نقاط کنترل زمینی&lt;/b&gt; (GCP_FILE): پروندهٔ &lt;i&gt;.points&lt;/i&gt; ابزار Georeferencer در QGIS (mapX,mapY,pixelX,pixelY,enable,…؛ pixelY منفیِ شمارهٔ سطر است) یا جدول CSV با ستون‌های id، col,row (یا pixel,line؛ یا image_x,image_y با قرارداد علامت QGIS)، X,Y (یا map_x,map_y / easting,northing) و ستون‌های اختیاری enabled (1/0)، role (gcp یا check) و weight. پرونده &lt;i&gt;یا&lt;/i&gt; یک لایهٔ نقطه‌ای را بدهید؛ اگر هیچ‌کدام داده نشود، پروندهٔ &lt;i&gt;&amp;lt;image&amp;gt;.points&lt;/i&gt; ابزار Georeferencer در کنار تصویر به کار می‌رود.&lt;/li&gt;&lt;li&gt;&lt;b&gt;لایهٔ نقطه‌ای نقاط کنترل&lt;/b&gt; (GCP_LAYER): نقاطی که هندسه‌شان مختصات نقشه‌ای را (در سیستم مختصات لایه) در خود دارد، با فیلدهایی برای ستون و سطر تصویر (COL_FIELD، ROW_FIELD) و فیلدهای اختیاری ID_FIELD، ENABLED_FIELD، ROLE_FIELD، WEIGHT_FIELD (وزن‌های کمترین مربعات، مثلاً 1/σ²؛ گزارش از آن‌ها استفاده می‌کند، اما warp در GDAL بدون وزن برازش می‌دهد).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مبدأ پیکسل&lt;/b&gt; (PIXEL_ORIGIN، پیش‌فرض 0 = گوشه): 0 — مختصات تصویر با قرارداد GDAL/QGIS، که در آن (0,0) گوشهٔ بالا-چپ تصویر و مرکز نخستین پیکسل (0.5, 0.5) است؛ 1 — مقادیر صحیح مراکز پیکسل‌اند (اندیس‌های آرایه از 0)، و 0.5 به آن‌ها افزوده می‌شود. سطرها همیشه رو به پایین افزایش می‌یابند (ستون سطرِ منفی به‌صورت −row در قرارداد QGIS خوانده می‌شود). پرونده‌های .points همیشه بر پایهٔ گوشه‌اند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;سیستم مختصات نقاط کنترل&lt;/b&gt; (GCP_CRS): سیستم مختصاتِ مختصات نقشه‌ای وقتی پرونده خط '#CRS:' ندارد (پرونده‌های CSV هرگز آن را ندارند). نبودِ سیستم مختصات خطا است.&lt;/li&gt;&lt;li&gt;&lt;b&gt;درجهٔ چندجمله‌ای&lt;/b&gt; (ORDER، 1–3، پیش‌فرض 1): 1 آفین (≥ 3 نقطهٔ کنترل)، 2 (≥ 6)، 3 (≥ 10).&lt;/li&gt;&lt;li&gt;&lt;b&gt;قدرت تفکیک زمینی GR&lt;/b&gt; (GR، واحد نقشه بر پیکسل، اختیاری): اندازهٔ پیکسل روی زمین برای معیارها؛ پیش‌فرض sqrt|det J| برازش آفین نقاط کنترل.&lt;/li&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Criteria&lt;/b&gt; (Tishreen Univ. J. Eng. Sci. 38(2), 2016): per-point RMS_i and contribution C_i = RMS_i/RMS_T; RMS_x, RMS_y, RMS_T with divisor n (and, labelled, n − N as the QGIS Georeferencer); map scale S = 20000·GR and tolerance band 4·GR … 6·GR for RMS_T; per-point limit 0.25 mm·S = 5·GR; ≥ 68 % (strict 90 %) of points within RMS_T; no directional bias (quadrant sign balance, inner vs edge radial residuals, residual-vector plot). Also: independent check points (role 'check', never fitted), leave-one-out residuals, orders 1–3 side by side with a recommended order (never one whose redundancy n − N is below max(2, ⌈N/2⌉)) and suggested points to drop. Residuals are predicted − given, in map units and pixels.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;معیارها&lt;/b&gt; (مجلهٔ علوم مهندسی دانشگاه تشرین 38(2)، 2016): RMS_i هر نقطه و سهم آن C_i = RMS_i/RMS_T؛ RMS_x، RMS_y و RMS_T با مقسوم‌علیه n (و، با برچسب جداگانه، n − N مانند Georeferencer در QGIS)؛ مقیاس نقشه S = 20000·GR و بازهٔ تلورانس 4·GR … 6·GR برای RMS_T؛ حد مجاز هر نقطه 0.25 mm·S = 5·GR؛ ≥ 68 % (در حالت سخت‌گیرانه 90 %) نقاط در محدودهٔ RMS_T؛ نبودِ سوگیری جهت‌دار (توازن علامت‌ها در ربع‌ها، باقی‌مانده‌های شعاعی نقاط درونی در برابر نقاط لبه، نمودار بردارهای باقی‌مانده). همچنین: نقاط چک مستقل (نقش 'check'، هرگز در برازش وارد نمی‌شوند)، باقی‌مانده‌های حذف‌یکی، درجه‌های 1–3 در کنار هم با یک درجهٔ پیشنهادی (هرگز درجه‌ای که افزونگی n − N آن کمتر از max(2, ⌈N/2⌉) باشد) و نقاط پیشنهادی برای حذف. باقی‌مانده‌ها برابر مقدار پیش‌بینی‌شده − مقدار داده‌شده‌اند، به واحد نقشه و پیکسل.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Returns filtered&lt;/b&gt; (RETURNS, default 0 = all): 0 all returns are classified and serve as neighbours (the forest study); 1 last returns only: only last (or single) returns are classified and only they may reject others; first and intermediate returns of multi-return pulses get class 1. Files without return numbers (e.g. the ISPRS samples) count every point as a last return.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Remove low outliers first&lt;/b&gt; (NOISE, default yes): points far below their neighbours (multipath) get class 7 and take no part in the filter — one stray low point would reject every ground point within r. Advanced: NOISE_RADIUS (m, default 5) and NOISE_THRESHOLD (m, default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Mode&lt;/b&gt; (MODE, default 0): 0 exact Vosselman rule; 1 terrain-adaptive (&lt;i&gt;this toolbox's extension&lt;/i&gt;): the rule is applied to heights above a smooth low terrain trend (minimum grid of TREND_CELL m, opening and mean filter of TREND_WINDOW m, defaults 10 and 60), so natural slopes steeper than θ are not rejected (ISPRS samp11, steep: total error 21.0 % → 16.4 % at the defaults). Because the terrain slope is removed first, lower θ (about 30–35°) usually works best in this mode.&lt;/li&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;بازگشت‌های فیلترشونده&lt;/b&gt; (RETURNS، پیش‌فرض 0 = همه): 0 همهٔ بازگشت‌ها طبقه‌بندی می‌شوند و به‌عنوان همسایه به کار می‌روند (مطالعهٔ جنگل)؛ 1 فقط بازگشت‌های آخر: فقط بازگشت‌های آخر (یا تکی) طبقه‌بندی می‌شوند و فقط آن‌ها می‌توانند نقاط دیگر را رد کنند؛ بازگشت‌های اول و میانیِ پالس‌های چندبازگشتی کلاس 1 می‌گیرند. در پرونده‌های بدون شمارهٔ بازگشت (مثلاً نمونه‌های ISPRS) هر نقطه بازگشت آخر به شمار می‌آید.&lt;/li&gt;&lt;li&gt;&lt;b&gt;حذف نقاط پرت پایین در آغاز&lt;/b&gt; (NOISE، پیش‌فرض: بله): نقاطی که بسیار پایین‌تر از همسایه‌های خود هستند (چندمسیری) کلاس 7 می‌گیرند و در فیلتر شرکت نمی‌کنند — یک نقطهٔ پایینِ سرگردان به‌تنهایی همهٔ نقاط زمینی درون r را رد می‌کرد. پیشرفته: NOISE_RADIUS (متر، پیش‌فرض 5) و NOISE_THRESHOLD (متر، پیش‌فرض 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حالت&lt;/b&gt; (MODE، پیش‌فرض 0): 0 قاعدهٔ دقیق Vosselman؛ 1 سازگار با ناهمواری زمین (&lt;i&gt;افزودهٔ این جعبه‌ابزار&lt;/i&gt;): قاعده روی ارتفاع‌ها نسبت به یک روند هموار و پایینِ زمین اعمال می‌شود (شبکهٔ کمینه با سلول TREND_CELL متر، بازشایی (opening) و فیلتر میانگین با پنجرهٔ TREND_WINDOW متر، پیش‌فرض‌ها 10 و 60)، پس شیب‌های طبیعیِ تندتر از θ رد نمی‌شوند (ISPRS samp11، پرشیب: خطای کل 21.0 % → 16.4 % با پیش‌فرض‌ها). چون شیب زمین از پیش حذف می‌شود، در این حالت θ کمتر (حدود 30–35°) معمولاً بهترین نتیجه را می‌دهد.&lt;/li&gt;</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): a .las or .laz file (LAS 1.0–1.4), e.g. the output of a ground filter.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classes used&lt;/b&gt; (CLASSES, default &lt;code&gt;2&lt;/code&gt; = ground): comma-separated LAS classes interpolated; empty = every point. No point of these classes → error that lists the classes present.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell size&lt;/b&gt; (CELL_SIZE, m, default 1.0, &amp;gt; 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Extent&lt;/b&gt; (EXTENT, optional): default = the selected points' extent. The grid is snapped outward to multiples of the cell size so that tiles line up.&lt;/li&gt;&lt;li&gt;&lt;b&gt;CRS&lt;/b&gt; (CRS, optional): overrides the CRS of the LAS file. If the file has no CRS and none is given the algorithm stops with an error (a DTM without a CRS is a common source of misplaced data).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Maximum distance to data&lt;/b&gt; (MAX_DISTANCE, m, default 0 = automatic: five mean point spacings, at least two cells): cells whose nearest point is farther are nodata, so no terrain is invented under water, removed buildings or missing strips.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Fill data gaps&lt;/b&gt; (FILL_GAPS, default no): interpolate every cell however far from the data (ignores MAX_DISTANCE).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Output&lt;/b&gt; (OUTPUT): GeoTIFF (float32, DEFLATE, nodata −9999) in the input CRS; values belong to cell centres.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional): HTML report.&lt;/li&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;ابر نقاط&lt;/b&gt; (INPUT): پروندهٔ .las یا .laz (LAS 1.0–1.4)، مثلاً خروجی یک فیلتر زمینی.&lt;/li&gt;&lt;li&gt;&lt;b&gt;کلاس‌های به‌کاررفته&lt;/b&gt; (CLASSES، پیش‌فرض &lt;code&gt;2&lt;/code&gt; = زمینی): کلاس‌های LAS که درون‌یابی می‌شوند، جداشده با ویرگول؛ خالی = همهٔ نقاط. نبودِ هیچ نقطه‌ای از این کلاس‌ها → خطایی که کلاس‌های موجود را فهرست می‌کند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;اندازهٔ سلول&lt;/b&gt; (CELL_SIZE، متر، پیش‌فرض 1.0، &amp;gt; 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;محدوده&lt;/b&gt; (EXTENT، اختیاری): پیش‌فرض = محدودهٔ نقاط انتخاب‌شده. شبکه رو به بیرون روی مضرب‌های اندازهٔ سلول تنظیم می‌شود تا کاشی‌ها با هم جفت شوند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;سیستم مختصات&lt;/b&gt; (CRS، اختیاری): سیستم مختصات پروندهٔ LAS را جایگزین می‌کند. اگر پرونده سیستم مختصات نداشته باشد و هیچ‌کدام داده نشود، الگوریتم با خطا متوقف می‌شود (مدل رقومی زمین بدون سیستم مختصات منبع رایج داده‌های نابه‌جا است).&lt;/li&gt;&lt;li&gt;&lt;b&gt;بیشینهٔ فاصله تا داده&lt;/b&gt; (MAX_DISTANCE، متر، پیش‌فرض 0 = خودکار: پنج برابر میانگین فاصلهٔ نقاط، دست‌کم دو سلول): سلول‌هایی که نزدیک‌ترین نقطه‌شان دورتر باشد nodata می‌شوند، تا زیر آب، ساختمان‌های حذف‌شده یا نوارهای گمشده زمینی ساختگی پدید نیاید.&lt;/li&gt;&lt;li&gt;&lt;b&gt;پر کردن شکاف‌های داده&lt;/b&gt; (FILL_GAPS، پیش‌فرض: خیر): درون‌یابی هر سلول، هر قدر هم از داده دور باشد (MAX_DISTANCE را نادیده می‌گیرد).&lt;/li&gt;&lt;li&gt;&lt;b&gt;خروجی&lt;/b&gt; (OUTPUT): GeoTIFF (float32، DEFLATE، nodata −9999) در سیستم مختصات ورودی؛ مقادیر به مراکز سلول‌ها تعلق دارند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML، اختیاری): گزارش HTML.&lt;/li&gt;</translation>
        </message>
        <message>
            <source>Remove low outliers first (class 7)</source>
            <translation>حذف نقاط پرت پایین در آغاز (کلاس 7)</translation>
        </message>
        <message>
            <source>Low-outlier search cell (m)</source>
            <translation>سلول جست‌وجوی نقاط پرت پایین (متر)</translation>
        </message>
        <message>
            <source>Low-outlier depth below neighbours (m)</source>
            <translation>عمق نقطهٔ پرت پایین نسبت به همسایه‌ها (متر)</translation>
        </message>
        <message>
            <source>Report language</source>
            <translation>زبان گزارش</translation>
        </message>
        <message>
            <source>Interface language</source>
            <translation>زبان رابط کاربری</translation>
        </message>
        <message>
            <source>Terminated; no output was written.</source>
            <translation>اجرا متوقف شد؛ هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Pick a loaded point-cloud layer or a .las/.laz file.</source>
            <translation>یک لایهٔ ابر نقاط بارشده یا یک فایل ‎.las/.laz‏ انتخاب کنید.</translation>
        </message>
        <message>
            <source>This QGIS build has no PDAL point-cloud provider, so point clouds cannot be loaded as layers: give the .las/.laz file.</source>
            <translation>این نسخهٔ QGIS ارائه‌دهندهٔ ابر نقاط PDAL ندارد، پس ابرهای نقاط را نمی‌توان به‌صورت لایه بار کرد: فایل ‎.las/.laz‏ را بدهید.</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>The point-cloud layer '{name}' is not a local .las/.laz file ({source}): export it to LAS/LAZ first.</source>
            <translation>لایهٔ ابر نقاط '{name}' یک فایل محلی ‎.las/.laz‏ نیست ({source}): ابتدا آن را به LAS/LAZ صادر کنید.</translation>
        </message>
        <message>
            <source>Created, never classified</source>
            <translation>ایجادشده، هرگز کلاس‌بندی‌نشده</translation>
        </message>
        <message>
            <source>Unclassified</source>
            <translation>کلاس‌بندی‌نشده</translation>
        </message>
        <message>
            <source>Ground</source>
            <translation>زمین</translation>
        </message>
        <message>
            <source>Low vegetation</source>
            <translation>پوشش گیاهی کوتاه</translation>
        </message>
        <message>
            <source>Medium vegetation</source>
            <translation>پوشش گیاهی متوسط</translation>
        </message>
        <message>
            <source>High vegetation</source>
            <translation>پوشش گیاهی بلند</translation>
        </message>
        <message>
            <source>Building</source>
            <translation>ساختمان</translation>
        </message>
        <message>
            <source>Low point (noise)</source>
            <translation>نقطهٔ پایین (نویز)</translation>
        </message>
        <message>
            <source>Reserved (model key-point)</source>
            <translation>رزروشده (نقطهٔ کلیدی مدل)</translation>
        </message>
        <message>
            <source>Water</source>
            <translation>آب</translation>
        </message>
        <message>
            <source>Rail</source>
            <translation>ریل</translation>
        </message>
        <message>
            <source>Road surface</source>
            <translation>سطح جاده</translation>
        </message>
        <message>
            <source>Reserved (overlap)</source>
            <translation>رزروشده (هم‌پوشانی)</translation>
        </message>
        <message>
            <source>Wire – guard (shield)</source>
            <translation>سیم – محافظ (شیلد)</translation>
        </message>
        <message>
            <source>Wire – conductor (phase)</source>
            <translation>سیم – رسانا (فاز)</translation>
        </message>
        <message>
            <source>Transmission tower</source>
            <translation>دکل انتقال نیرو</translation>
        </message>
        <message>
            <source>Wire-structure connector (insulator)</source>
            <translation>اتصال سیم به سازه (مقره)</translation>
        </message>
        <message>
            <source>Bridge deck</source>
            <translation>عرشهٔ پل</translation>
        </message>
        <message>
            <source>High noise</source>
            <translation>نویز بالا</translation>
        </message>
        <message>
            <source>Overhead structure</source>
            <translation>سازهٔ هوایی</translation>
        </message>
        <message>
            <source>Ignored ground</source>
            <translation>زمین نادیده‌گرفته</translation>
        </message>
        <message>
            <source>Snow</source>
            <translation>برف</translation>
        </message>
        <message>
            <source>Temporal exclusion</source>
            <translation>حذف زمانی</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Classified point cloud&lt;/b&gt; (OUTPUT, .laz/.las): every point with class 2 ground, 1 other or 7 low noise; every other attribute, VLR and the CRS copied unchanged.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground points&lt;/b&gt; (GROUND_OUTPUT, optional): only the ground points.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional) in REPORT_LANGUAGE (advanced).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Keep existing noise classes&lt;/b&gt; (KEEP_NOISE, advanced, default yes): points already classified 7 or 18 keep their class and take no part.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: N_POINTS, N_GROUND, N_NONGROUND, N_NOISE (class 7), POINTS_PER_SECOND (filter step only).&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;ابر نقاط طبقه‌بندی‌شده&lt;/b&gt; (OUTPUT، ‎.laz/.las): هر نقطه با کلاس 2 زمین، 1 دیگر یا 7 نویز پایین؛ همهٔ ویژگی‌های دیگر، VLRها و سیستم مختصات بی‌تغییر کپی می‌شوند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نقاط زمین&lt;/b&gt; (GROUND_OUTPUT، اختیاری): فقط نقاط زمین.&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML، اختیاری) به زبان REPORT_LANGUAGE (پیشرفته).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حفظ کلاس‌های نویز موجود&lt;/b&gt; (KEEP_NOISE، پیشرفته، پیش‌فرض بله): نقاطی که از پیش 7 یا 18 هستند کلاس خود را نگه می‌دارند و شرکت نمی‌کنند.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;اعداد خروجی: N_POINTS، N_GROUND، N_NONGROUND، N_NOISE (کلاس 7)، POINTS_PER_SECOND (فقط گام فیلتر).&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Transformation&lt;/b&gt; (TRANSFORMATION, default 0): 0 polynomial of order ORDER; 1–3 polynomial of order 1, 2, 3; 4 linear (shift and scale per axis, ≥ 2 GCPs); 5 Helmert (shift, one scale, one rotation, ≥ 2); 6 projective (homography, ≥ 4); 7 thin-plate spline (through every GCP, ≥ 3, as gdalwarp -tps); 8 recommended: every transformation is compared and the one with the lowest check-point (else leave-one-out) error is used, the simplest within 10 % of the best.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Refine GCPs&lt;/b&gt; (REFINE, default off): as gdalwarp -refine_gcps, drop the GCP with the largest residual while it exceeds the tolerance, then refit; the dropped points are listed in the report.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Refinement tolerance&lt;/b&gt; (REFINE_TOLERANCE, map units, default the C5 per-point limit 0.25 mm·S = 5·GR).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum GCPs&lt;/b&gt; (MIN_GCPS, default the transformation's minimum + 2): the refinement never goes below this count.&lt;/li&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;تبدیل&lt;/b&gt; (TRANSFORMATION، پیش‌فرض 0): 0 چندجمله‌ای درجهٔ ORDER؛ 1–3 چندجمله‌ای درجهٔ 1، 2، 3؛ 4 خطی (انتقال و مقیاس برای هر محور، ≥ 2 نقطه)؛ 5 هلمرت (انتقال، یک مقیاس، یک دوران، ≥ 2)؛ 6 تصویری (هموگرافی، ≥ 4)؛ 7 اسپلاین صفحهٔ نازک (از همهٔ نقاط می‌گذرد، ≥ 3، مانند gdalwarp -tps)؛ 8 پیشنهادی: همهٔ تبدیل‌ها مقایسه می‌شوند و تبدیلی با کمترین خطای نقاط چک (وگرنه حذف‌یکی) به کار می‌رود، ساده‌ترین در محدودهٔ 10 % بهترین.&lt;/li&gt;&lt;li&gt;&lt;b&gt;پالایش نقاط&lt;/b&gt; (REFINE، پیش‌فرض خاموش): مانند gdalwarp -refine_gcps، نقطهٔ با بزرگ‌ترین باقیمانده تا وقتی از تلورانس بیشتر است حذف و برازش تکرار می‌شود؛ نقاط حذف‌شده در گزارش فهرست می‌شوند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;تلورانس پالایش&lt;/b&gt; (REFINE_TOLERANCE، واحد نقشه، پیش‌فرض حد نقطه‌ای C5 یعنی 0.25 mm·S = 5·GR).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حداقل نقاط&lt;/b&gt; (MIN_GCPS، پیش‌فرض حداقل تبدیل + 2): پالایش هرگز به کمتر از این تعداد نمی‌رسد.&lt;/li&gt;</translation>
        </message>
    </context>
    <context>
        <name>GeomaticsProvider</name>
        <message>
            <source>Geomatics Toolbox</source>
            <translation>جعبه‌ابزار ژئوماتیک</translation>
        </message>
        <message>
            <source>LiDAR to DTM with accuracy</source>
            <translation>از LiDAR تا DTM همراه با دقت</translation>
        </message>
    </context>
    <context>
        <name>GroundFilterAccuracyAlgorithm</name>
        <message>
            <source>Ground filter accuracy</source>
            <translation>دقت فیلتر نقاط زمینی</translation>
        </message>
        <message>
            <source>lidar,ground,filter,accuracy,type i,type ii,total error,kappa,isprs,reference,confusion matrix</source>
            <translation>لایدار,زمین,فیلتر,دقت,نوع اول,نوع دوم,خطای کل,کاپا,isprs,مرجع,ماتریس درهم‌ریختگی</translation>
        </message>
        <message>
            <source>&lt;p&gt;Compares a filtered point cloud with reference labels, with the measures of the ISPRS filter test (Sithole &amp;amp; Vosselman 2004): the cross matrix a (ground kept), b (ground rejected), c (object accepted), d (object rejected), Type I = b/(a+b), Type II = c/(c+d), total = (b+c)/n and Cohen's kappa.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=classified.laz REFERENCE=samp54.laz (the ISPRS reference sample, class 2 = ground) OUTPUT_HTML=accuracy.html.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Filtered point cloud&lt;/b&gt; (INPUT, LAS/LAZ).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Class dimension of the filtered cloud&lt;/b&gt; (FIELD, default classification) and its &lt;b&gt;ground classes&lt;/b&gt; (GROUND_CLASSES, default 2; a list such as 2,8 is accepted). Every other class (1, 7 noise, 0...) counts as object.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Reference point cloud&lt;/b&gt; (REFERENCE, optional): the same points in the same order (checked: equal count and coordinates). When empty, the reference labels are read from another dimension of INPUT.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Reference class dimension&lt;/b&gt; (REFERENCE_FIELD, default classification; e.g. user_data or an extra dimension when there is no reference cloud) and its &lt;b&gt;ground classes&lt;/b&gt; (REFERENCE_GROUND_CLASSES, default 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional): the matrix, the errors, and the reference labels of every filtered class.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Per-point error layer&lt;/b&gt; (ERROR_OUTPUT, optional LAS/LAZ): a copy of INPUT, every attribute unchanged except &lt;i&gt;user_data&lt;/i&gt; = 0 correct, 1 Type I (ground rejected), 2 Type II (object accepted); style the point cloud layer by user_data to map where the filter fails.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Outputs A, B, C, D, N, TYPE1, TYPE2, TOTAL and KAPPA are numbers for the graphical modeler.&lt;/p&gt;</source>
            <translation>&lt;p&gt;یک ابر نقاط فیلترشده را با برچسب‌های مرجع مقایسه می‌کند، با سنجه‌های آزمون فیلترهای ISPRS (Sithole &amp; Vosselman 2004): ماتریس متقاطع a (زمینیِ نگه‌داشته)، b (زمینیِ ردشده)، c (عارضهٔ پذیرفته‌شده)، d (عارضهٔ ردشده)، نوع اول = b/(a+b)، نوع دوم = c/(c+d)، کل = (b+c)/n و ضریب کاپای کوهن.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=classified.laz REFERENCE=samp54.laz (نمونهٔ مرجع ISPRS، کلاس 2 = زمین) OUTPUT_HTML=accuracy.html.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;ابر نقاط فیلترشده&lt;/b&gt; (INPUT، LAS/LAZ).&lt;/li&gt;&lt;li&gt;&lt;b&gt;بُعد کلاس ابر فیلترشده&lt;/b&gt; (FIELD، پیش‌فرض classification) و &lt;b&gt;کلاس‌های زمینی&lt;/b&gt; آن (GROUND_CLASSES، پیش‌فرض 2؛ فهرستی مانند 2,8 هم پذیرفته می‌شود). هر کلاس دیگر (1، 7 نویز، 0...) عارضه به شمار می‌آید.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ابر نقاط مرجع&lt;/b&gt; (REFERENCE، اختیاری): همان نقاط با همان ترتیب (بررسی می‌شود: تعداد و مختصات برابر). اگر خالی باشد، برچسب‌های مرجع از بُعد دیگری از INPUT خوانده می‌شوند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;بُعد کلاس مرجع&lt;/b&gt; (REFERENCE_FIELD، پیش‌فرض classification؛ مثلاً user_data یا یک بُعد اضافی وقتی ابر مرجعی در کار نیست) و &lt;b&gt;کلاس‌های زمینی&lt;/b&gt; آن (REFERENCE_GROUND_CLASSES، پیش‌فرض 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML، اختیاری): ماتریس، خطاها و برچسب‌های مرجعِ هر کلاس فیلترشده.&lt;/li&gt;&lt;li&gt;&lt;b&gt;لایهٔ خطای نقطه‌به‌نقطه&lt;/b&gt; (ERROR_OUTPUT، LAS/LAZ اختیاری): رونوشتی از INPUT که همهٔ ویژگی‌ها در آن بدون تغییر است جز &lt;i&gt;user_data&lt;/i&gt; = 0 درست، 1 نوع اول (زمینیِ ردشده)، 2 نوع دوم (عارضهٔ پذیرفته‌شده)؛ لایهٔ ابر نقاط را بر پایهٔ user_data نمادپردازی کنید تا ببینید فیلتر کجا خطا می‌کند.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;خروجی‌های A، B، C، D، N، TYPE1، TYPE2، TOTAL و KAPPA اعدادی برای طراح گرافیکی مدل هستند.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Filtered point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط فیلترشده (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Class dimension of the filtered cloud</source>
            <translation>بُعد کلاس ابر فیلترشده</translation>
        </message>
        <message>
            <source>Ground classes of the filtered cloud</source>
            <translation>کلاس‌های زمینی ابر فیلترشده</translation>
        </message>
        <message>
            <source>Reference point cloud (same points, same order)</source>
            <translation>ابر نقاط مرجع (همان نقاط، با همان ترتیب)</translation>
        </message>
        <message>
            <source>Reference class dimension</source>
            <translation>بُعد کلاس مرجع</translation>
        </message>
        <message>
            <source>Reference ground classes</source>
            <translation>کلاس‌های زمینی مرجع</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>Per-point error layer (user_data: 0 correct, 1 Type I, 2 Type II)</source>
            <translation>لایهٔ خطای نقطه‌به‌نقطه (user_data: 0 درست، 1 نوع اول، 2 نوع دوم)</translation>
        </message>
        <message>
            <source>The error layer must end in .las or .laz: {p}</source>
            <translation>پروندهٔ لایهٔ خطا باید پسوند .las یا .laz داشته باشد: {p}</translation>
        </message>
    </context>
    <context>
        <name>GroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (recommended)</source>
            <translation>فیلتر زمین (پیشنهادی)</translation>
        </message>
        <message>
            <source>Classifies ground in a LAS/LAZ cloud with no parameter to set.</source>
            <translation>زمین را در ابر LAS/LAZ بدون هیچ پارامتری که لازم به تنظیم باشد طبقه‌بندی می‌کند.</translation>
        </message>
        <message>
            <source>&lt;p&gt;Classifies a LAS/LAZ point cloud into ground (class 2), other points (class 1) and low noise (class 7) with no parameter to set: a progressive morphological filter (Pingel et al. 2013, after Zhang et al. 2003) whose raster cell and slope tolerance are derived from the cloud itself (point density, terrain slope), followed by three passes that rebuild the terrain from the points accepted and re-test every point against it.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=tile.laz OUTPUT=classified.laz — nothing else.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Measured accuracy&lt;/b&gt; (total error, Sithole &amp;amp; Vosselman 2004) on the 8 ISPRS filter-test samples 11, 12, 22, 31, 41, 53, 54, 61: mean 4.06 % at these defaults; SMRF with PDAL's defaults 5.75 % in the same script. The defaults were chosen on these samples: the honest, cross-validated figure (leave one sample out) is 4.42 %; worst sample 9.82 % (samp11, steep terrain with buildings). Beats SMRF on 5 of the 8 samples.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las or .laz in a projected CRS (metres); 0.2 to 20+ points/m².&lt;/li&gt;&lt;li&gt;Advanced overrides (0 = derived from the cloud): &lt;b&gt;CELL&lt;/b&gt; (m, default 0 → 1 m), &lt;b&gt;MAX_WINDOW&lt;/b&gt; (m, default 18; must exceed the largest building), &lt;b&gt;SLOPE&lt;/b&gt; (rise/run, default 0 → 0.5 × local terrain slope, 0.10 to 0.60), &lt;b&gt;THRESHOLD&lt;/b&gt; (m, default 0.5; plus 1.25 m per unit of terrain slope), &lt;b&gt;REFINE&lt;/b&gt; (passes, default 3).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Remove low outliers first&lt;/b&gt; (NOISE, advanced, default no): the filter finds low noise itself; yes runs the shared pre-filter first (NOISE_RADIUS m, default 5; NOISE_THRESHOLD m, default 1).&lt;/li&gt;</source>
            <translation>&lt;p&gt;ابر نقاط LAS/LAZ را بدون هیچ پارامتری که لازم به تنظیم باشد به زمین (کلاس 2)، نقاط دیگر (کلاس 1) و نویز پایین (کلاس 7) طبقه‌بندی می‌کند: یک فیلتر ریخت‌شناسی تدریجی (Pingel و همکاران 2013، برگرفته از Zhang و همکاران 2003) که سلول رستر و تلورانس شیب آن از خود ابر (تراکم نقاط، شیب زمین) به دست می‌آید، و سپس سه گذر که زمین را از نقاط پذیرفته‌شده دوباره می‌سازند و هر نقطه را دوباره با آن می‌آزمایند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=tile.laz OUTPUT=classified.laz — نه چیز دیگر.&lt;/p&gt;&lt;p&gt;&lt;b&gt;دقت اندازه‌گیری‌شده&lt;/b&gt; (خطای کل، Sithole &amp;amp; Vosselman 2004) روی 8 نمونهٔ آزمون فیلتر ISPRS ‏11، 12، 22، 31، 41، 53، 54، 61: میانگین 4.06 % با این پیش‌فرض‌ها؛ SMRF با پیش‌فرض‌های PDAL در همان اسکریپت 5.75 %. پیش‌فرض‌ها روی همین نمونه‌ها انتخاب شده‌اند: عدد صادقانهٔ اعتبارسنجی متقابل (کنار گذاشتن یک نمونه) 4.42 % است؛ بدترین نمونه 9.82 % (samp11، زمین پرشیب با ساختمان). در 5 نمونه از 8 نمونه از SMRF بهتر است.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;ابر نقاط&lt;/b&gt; (INPUT): فایل ‎.las یا ‎.laz در سیستم مختصات تصویری (متر)؛ از 0.2 تا بیش از 20 نقطه بر متر مربع.&lt;/li&gt;&lt;li&gt;جایگزین‌های پیشرفته (0 = برگرفته از ابر): &lt;b&gt;CELL&lt;/b&gt; (متر، پیش‌فرض 0 ← 1 متر)، &lt;b&gt;MAX_WINDOW&lt;/b&gt; (متر، پیش‌فرض 18؛ باید از بزرگ‌ترین ساختمان بزرگ‌تر باشد)، &lt;b&gt;SLOPE&lt;/b&gt; (ارتفاع/فاصله، پیش‌فرض 0 ← 0.5 × شیب محلی زمین، از 0.10 تا 0.60)، &lt;b&gt;THRESHOLD&lt;/b&gt; (متر، پیش‌فرض 0.5؛ به‌علاوهٔ 1.25 متر به ازای هر واحد شیب زمین)، &lt;b&gt;REFINE&lt;/b&gt; (گذرها، پیش‌فرض 3).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حذف نقاط پرت پایین در آغاز&lt;/b&gt; (NOISE، پیشرفته، پیش‌فرض خیر): فیلتر خودش نویز پایین را می‌یابد؛ بله پیش‌فیلتر مشترک را اول اجرا می‌کند (NOISE_RADIUS متر، پیش‌فرض 5؛ NOISE_THRESHOLD متر، پیش‌فرض 1).&lt;/li&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;References: Pingel, T. J., Clarke, K. C. &amp;amp; McBride, W. A. (2013), ISPRS J. Photogramm. Remote Sens. 77, 21–30; Zhang, K. et al. (2003), IEEE TGRS 41(4), 872–882.&lt;/p&gt;</source>
            <translation>&lt;p&gt;مراجع: Pingel, T. J., Clarke, K. C. &amp;amp; McBride, W. A. (2013), ISPRS J. Photogramm. Remote Sens. 77, 21–30؛ Zhang, K. et al. (2003), IEEE TGRS 41(4), 872–882.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Raster cell, 0 = derived (m)</source>
            <translation>سلول رستر، 0 = برگرفته (متر)</translation>
        </message>
        <message>
            <source>Largest window, &gt; largest building (m)</source>
            <translation>بزرگ‌ترین پنجره، &gt; بزرگ‌ترین ساختمان (متر)</translation>
        </message>
        <message>
            <source>Slope tolerance, 0 = derived (rise/run)</source>
            <translation>تلورانس شیب، 0 = برگرفته (ارتفاع/فاصله)</translation>
        </message>
        <message>
            <source>Height tolerance (m)</source>
            <translation>تلورانس ارتفاع (متر)</translation>
        </message>
        <message>
            <source>Refinement passes</source>
            <translation>گذرهای پالایش</translation>
        </message>
        <message>
            <source>Remove low outliers first (class 7)</source>
            <translation>حذف نقاط پرت پایین در آغاز (کلاس 7)</translation>
        </message>
        <message>
            <source>Low-outlier search cell (m)</source>
            <translation>سلول جست‌وجوی نقاط پرت پایین (متر)</translation>
        </message>
        <message>
            <source>Low-outlier depth below neighbours (m)</source>
            <translation>عمق نقطهٔ پرت پایین نسبت به همسایه‌ها (متر)</translation>
        </message>
        <message>
            <source>Recommended ground filter: window {} m, threshold {} m, {} refinement passes</source>
            <translation>فیلتر زمین پیشنهادی: پنجره {} متر، آستانه {} متر، {} گذر پالایش</translation>
        </message>
    </context>
    <context>
        <name>GsdBatchAlgorithm</name>
        <message>
            <source>GSD and photogrammetric accuracy calculator (batch table)</source>
            <translation>محاسبه‌گر GSD و دقت فتوگرامتری (جدول دسته‌ای)</translation>
        </message>
        <message>
            <source>&lt;p&gt;Runs the GSD / accuracy calculator for every row of a table (CSV, spreadsheet or any layer) and writes a table with the inputs and all results.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Input columns&lt;/b&gt; (case-insensitive): &lt;i&gt;camera&lt;/i&gt; (optional preset key: nikon_p100, dji_p4rtk, dji_p1_35, phaseone_ixm100_80), &lt;i&gt;distance&lt;/i&gt; (m, required), &lt;i&gt;sensor_width&lt;/i&gt; (mm), &lt;i&gt;image_width&lt;/i&gt; (px), &lt;i&gt;focal_length&lt;/i&gt; (mm) — required unless a camera preset is given — and optionally sensor_height, image_height, target_gsd, k_m, k_s, pyramid_level, subsampling_step, observed_sx, observed_sy, observed_sz, observed_sxyz, observed_dense_std, forward_overlap, side_overlap, stereo_base (units as in the single calculator).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Output&lt;/b&gt;: the input columns plus gsd_cm, footprint_width_m, sigma_xyz_mm, dense_resolution_cm and every other result. A row with an invalid value stops the run with an error naming the row and column.&lt;/p&gt;</source>
            <translation>&lt;p&gt;محاسبه‌گر GSD و دقت را برای هر ردیف یک جدول (CSV، صفحه‌گسترده یا هر لایه) اجرا می‌کند و جدولی با ورودی‌ها و همهٔ نتایج می‌نویسد.&lt;/p&gt;&lt;p&gt;&lt;b&gt;ستون‌های ورودی&lt;/b&gt; (بدون حساسیت به حروف بزرگ و کوچک): &lt;i&gt;camera&lt;/i&gt; (اختیاری، کلید دوربین: nikon_p100، dji_p4rtk، dji_p1_35، phaseone_ixm100_80)، &lt;i&gt;distance&lt;/i&gt; (متر، الزامی)، &lt;i&gt;sensor_width&lt;/i&gt; (میلی‌متر)، &lt;i&gt;image_width&lt;/i&gt; (پیکسل)، &lt;i&gt;focal_length&lt;/i&gt; (میلی‌متر) — الزامی مگر آنکه دوربین داده شود — و به‌اختیار sensor_height، image_height، target_gsd، k_m، k_s، pyramid_level، subsampling_step، observed_sx، observed_sy، observed_sz، observed_sxyz، observed_dense_std، forward_overlap، side_overlap، stereo_base (با همان واحدهای محاسبه‌گر تکی).&lt;/p&gt;&lt;p&gt;&lt;b&gt;خروجی&lt;/b&gt;: ستون‌های ورودی به‌علاوهٔ gsd_cm، footprint_width_m، sigma_xyz_mm، dense_resolution_cm و دیگر نتایج. ردیفی با مقدار نامعتبر اجرا را با پیامی که ردیف و ستون را نام می‌برد متوقف می‌کند.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Table of cameras and distances</source>
            <translation>جدول دوربین‌ها و فاصله‌ها</translation>
        </message>
        <message>
            <source>Round GSD to 0.01 cm/px like the paper</source>
            <translation>گرد کردن GSD به ۰٫۰۱ سانتی‌متر/پیکسل مانند مقاله</translation>
        </message>
        <message>
            <source>GSD results</source>
            <translation>نتایج GSD</translation>
        </message>
        <message>
            <source>The table has no 'distance' column (m); columns found: {0}.</source>
            <translation>جدول ستون 'distance' (متر) ندارد؛ ستون‌های موجود: {0}.</translation>
        </message>
        <message>
            <source>Row {row}: unknown camera '{cam}'; known: {known}.</source>
            <translation>ردیف {row}: دوربین ناشناختهٔ '{cam}'؛ دوربین‌های شناخته: {known}.</translation>
        </message>
        <message>
            <source>Row {row}, column '{col}': '{val}' is not a number.</source>
            <translation>ردیف {row}، ستون '{col}': مقدار '{val}' عدد نیست.</translation>
        </message>
        <message>
            <source>Row {row}: missing {cols}; give the columns or a camera preset.</source>
            <translation>ردیف {row}: مقادیر {cols} وجود ندارد؛ ستون‌ها یا یک دوربین از پیش تعریف‌شده بدهید.</translation>
        </message>
        <message>
            <source>Row {row}: {err}</source>
            <translation>ردیف {row}: {err}</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Round GSD like the paper&lt;/b&gt; (ROUND_GSD, default no): round the GSD to 0.01 cm/px before the derived quantities.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;گرد کردن GSD مانند مقاله&lt;/b&gt; (ROUND_GSD، پیش‌فرض: خیر): GSD را پیش از محاسبهٔ کمیت‌های وابسته به ۰٫۰۱ سانتی‌متر/پیکسل گرد می‌کند.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Could not write the result table: {0}</source>
            <translation>نوشتن جدول نتایج ممکن نشد: {0}</translation>
        </message>
    </context>
    <context>
        <name>GsdCalculatorAlgorithm</name>
        <message>
            <source>GSD and photogrammetric accuracy calculator</source>
            <translation>محاسبه‌گر GSD (فاصلهٔ نمونه‌برداری زمینی) و دقت فتوگرامتری</translation>
        </message>
        <message>
            <source>gsd,ground sampling distance,flying height,footprint,accuracy,photogrammetry,drone,flight planning,dense matching</source>
            <translation>gsd,فاصله نمونه‌برداری زمینی,ارتفاع پرواز,پوشش زمینی,دقت,فتوگرامتری,پهپاد,طراحی پرواز,تناظریابی متراکم</translation>
        </message>
        <message>
            <source>Custom (enter the values below)</source>
            <translation>سفارشی (مقادیر زیر را وارد کنید)</translation>
        </message>
        <message>
            <source>Camera preset</source>
            <translation>دوربین از پیش تعریف‌شده</translation>
        </message>
        <message>
            <source>Camera–object distance / flying height (m)</source>
            <translation>فاصلهٔ دوربین تا شیء / ارتفاع پرواز (متر)</translation>
        </message>
        <message>
            <source>Sensor height (mm)</source>
            <translation>ارتفاع حسگر (میلی‌متر)</translation>
        </message>
        <message>
            <source>Image height (px)</source>
            <translation>ارتفاع تصویر (پیکسل)</translation>
        </message>
        <message>
            <source>Target GSD (cm/px)</source>
            <translation>GSD هدف (سانتی‌متر/پیکسل)</translation>
        </message>
        <message>
            <source>Round GSD to 0.01 cm/px like the paper</source>
            <translation>گرد کردن GSD به ۰٫۰۱ سانتی‌متر/پیکسل مانند مقاله</translation>
        </message>
        <message>
            <source>Measurement factor k_m (px)</source>
            <translation>ضریب اندازه‌گیری k_m (پیکسل)</translation>
        </message>
        <message>
            <source>Safety factor k_s</source>
            <translation>ضریب اطمینان k_s</translation>
        </message>
        <message>
            <source>Dense matching pyramid level N_p (fraction, or % if checked below)</source>
            <translation>سطح هرم تصویر در تناظریابی متراکم N_p (کسر، یا درصد اگر گزینهٔ زیر فعال باشد)</translation>
        </message>
        <message>
            <source>Pyramid level is a percentage</source>
            <translation>سطح هرم به درصد است</translation>
        </message>
        <message>
            <source>Dense matching subsampling step T_s (px)</source>
            <translation>گام نمونه‌برداری تناظریابی متراکم T_s (پیکسل)</translation>
        </message>
        <message>
            <source>Observed σx (mm)</source>
            <translation>σx مشاهده‌شده (میلی‌متر)</translation>
        </message>
        <message>
            <source>Observed σy (mm)</source>
            <translation>σy مشاهده‌شده (میلی‌متر)</translation>
        </message>
        <message>
            <source>Observed σz (mm)</source>
            <translation>σz مشاهده‌شده (میلی‌متر)</translation>
        </message>
        <message>
            <source>Observed σxyz (mm)</source>
            <translation>σxyz مشاهده‌شده (میلی‌متر)</translation>
        </message>
        <message>
            <source>Observed dense-cloud std (cm)</source>
            <translation>انحراف معیار مشاهده‌شدهٔ ابر نقاط متراکم (سانتی‌متر)</translation>
        </message>
        <message>
            <source>Stereo base B (m) [extension]</source>
            <translation>طول باز استریو B (متر) [افزوده]</translation>
        </message>
        <message>
            <source>Forward overlap (%) [extension]</source>
            <translation>پوشش طولی (%) [افزوده]</translation>
        </message>
        <message>
            <source>Side overlap (%) [extension]</source>
            <translation>پوشش عرضی (%) [افزوده]</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>{name} ({unit}) is required with the Custom camera: enter it or choose a camera preset.</source>
            <translation>مقدار {name} ({unit}) برای دوربین سفارشی لازم است: آن را وارد کنید یا یک دوربین از پیش تعریف‌شده برگزینید.</translation>
        </message>
        <message>
            <source>Ground sampling distance, footprint and theoretical photogrammetric accuracy of a camera at a distance.</source>
            <translation>فاصلهٔ نمونه‌برداری زمینی، پوشش زمینی و دقت نظری فتوگرامتری یک دوربین در یک فاصلهٔ معین.</translation>
        </message>
        <message>
            <source>&lt;p&gt;Computes the ground sampling distance (GSD) and footprint of a camera at a given distance or flying height. It also gives the theoretical accuracy of phototriangulation and of a dense-matching cloud, and compares observed accuracies with it (Al Khalil 2019).&lt;/p&gt;</source>
            <translation>&lt;p&gt;فاصلهٔ نمونه‌برداری زمینی (GSD) و پوشش زمینی یک دوربین را در فاصله یا ارتفاع پرواز معین محاسبه می‌کند. همچنین دقت نظری مثلث‌بندی هوایی و ابر نقاط تناظریابی متراکم را می‌دهد و دقت مشاهده‌شده را با آن مقایسه می‌کند (الخلیل ۲۰۱۹).&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: the paper's Nikon Coolpix P100 at 5.88 m (sensor width 6.123 mm, image width 3648 px, focal length 4.6 mm) gives a GSD of 0.21455 cm/px, σ&lt;sub&gt;xyz&lt;/sub&gt; 1.287 mm (1.26 mm with the rounded GSD), a dense-cloud resolution of 0.858 cm and a footprint 7.827 m wide.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: دوربین Nikon Coolpix P100 مقاله در فاصلهٔ ‎5.88 m‏ (عرض حسگر ‎6.123 mm‏، عرض تصویر ‎3648 px‏، فاصلهٔ کانونی ‎4.6 mm‏) GSD برابر ‎0.21455 cm/px‏، σ&lt;sub&gt;xyz&lt;/sub&gt; برابر ‎1.287 mm‏ (‎1.26 mm‏ با GSD گردشده)، تفکیک ابر متراکم ‎0.858 cm‏ و پوشش زمینی به عرض ‎7.827 m‏ می‌دهد.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Formulas&lt;/b&gt;: GSD [cm/px] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;); footprint = D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;; σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD; σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;; matching step P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;; dense resolution R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;فرمول‌ها&lt;/b&gt;: &lt;span dir="ltr"&gt;GSD [cm/px] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;)&lt;/span&gt;؛ پوشش زمینی = &lt;span dir="ltr"&gt;D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;&lt;/span&gt;؛ &lt;span dir="ltr"&gt;σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD&lt;/span&gt;؛ &lt;span dir="ltr"&gt;σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;&lt;/span&gt;؛ گام تناظریابی &lt;span dir="ltr"&gt;P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;&lt;/span&gt;؛ تفکیک ابر متراکم &lt;span dir="ltr"&gt;R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD&lt;/span&gt;.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Camera preset&lt;/b&gt; (default Custom): fills the sensor, image and focal length values; values you enter override the preset.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Distance&lt;/b&gt; (m, default 100): camera–object distance or flying height above ground, &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Sensor width&lt;/b&gt; (mm), &lt;b&gt;image width&lt;/b&gt; (px) and &lt;b&gt;focal length&lt;/b&gt; (mm, the true focal length, not the 35 mm equivalent): required with the Custom camera.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Sensor height&lt;/b&gt; (mm) / &lt;b&gt;image height&lt;/b&gt; (px): optional, for the footprint height and the flight spacing.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Target GSD&lt;/b&gt; (cm/px): optional; gives the distance that achieves it.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Round GSD like the paper&lt;/b&gt; (default no): round the GSD to 0.01 cm/px before the derived quantities.&lt;/li&gt;&lt;li&gt;&lt;b&gt;k&lt;sub&gt;m&lt;/sub&gt;&lt;/b&gt; (px, default 0.3; 0.13 for an expert operator) and &lt;b&gt;k&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (default 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Pyramid level N&lt;sub&gt;p&lt;/sub&gt;&lt;/b&gt; (default 0.5, a fraction in (0, 1], or a percentage) and &lt;b&gt;subsampling step T&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (px, ≥ 1, default 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Observed σx, σy, σz, σxyz&lt;/b&gt; (mm) and &lt;b&gt;observed dense-cloud std&lt;/b&gt; (cm): optional; give the observed/theoretical ratios.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Extension&lt;/b&gt; (not in the paper): stereo base (m) gives the normal-case σ&lt;sub&gt;Z&lt;/sub&gt;; forward/side overlap (%) give the exposure and line spacing.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GSD calculator report&lt;/b&gt;: optional HTML report.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Every result is also an output number, so the graphical modeler can chain it.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;دوربین از پیش تعریف‌شده&lt;/b&gt; (پیش‌فرض: سفارشی): مقادیر حسگر، تصویر و فاصلهٔ کانونی را پر می‌کند؛ مقادیری که وارد کنید بر آن مقدم‌اند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;فاصله&lt;/b&gt; (m، پیش‌فرض 100): فاصلهٔ دوربین تا شیء یا ارتفاع پرواز از زمین، &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;عرض حسگر&lt;/b&gt; (mm)، &lt;b&gt;عرض تصویر&lt;/b&gt; (px) و &lt;b&gt;فاصلهٔ کانونی&lt;/b&gt; (mm، فاصلهٔ کانونی واقعی نه معادل 35 mm): با دوربین «سفارشی» الزامی‌اند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ارتفاع حسگر&lt;/b&gt; (mm) / &lt;b&gt;ارتفاع تصویر&lt;/b&gt; (px): اختیاری، برای ارتفاع پوشش زمینی و فاصله‌گذاری پرواز.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GSD هدف&lt;/b&gt; (cm/px): اختیاری؛ فاصله‌ای را می‌دهد که به آن می‌رسد.&lt;/li&gt;&lt;li&gt;&lt;b&gt;گرد کردن GSD مانند مقاله&lt;/b&gt; (پیش‌فرض: خیر): GSD را پیش از کمیت‌های مشتق به ‎0.01 cm/px‏ گرد می‌کند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;k&lt;sub&gt;m&lt;/sub&gt;&lt;/b&gt; (px، پیش‌فرض 0.3؛ 0.13 برای اپراتور خبره) و &lt;b&gt;k&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (پیش‌فرض 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;سطح هرم N&lt;sub&gt;p&lt;/sub&gt;&lt;/b&gt; (پیش‌فرض 0.5، کسری در (0، 1]، یا درصد) و &lt;b&gt;گام زیرنمونه‌برداری T&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (px، ≥ 1، پیش‌فرض 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;σx، σy، σz، σxyz مشاهده‌شده&lt;/b&gt; (mm) و &lt;b&gt;انحراف معیار مشاهده‌شدهٔ ابر متراکم&lt;/b&gt; (cm): اختیاری؛ نسبت مشاهده‌شده به نظری را می‌دهند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;افزوده&lt;/b&gt; (در مقاله نیست): باز استریو (m) σ&lt;sub&gt;Z&lt;/sub&gt; حالت نرمال را می‌دهد؛ همپوشانی طولی/عرضی (%) فاصلهٔ عکس‌ها و فاصلهٔ خطوط پرواز را می‌دهد.&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش محاسبه‌گر GSD&lt;/b&gt;: گزارش HTML اختیاری.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;هر نتیجه یک عدد خروجی نیز هست، پس در مدل‌ساز گرافیکی قابل زنجیره‌شدن است.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Required with the Custom camera; overrides the preset.</source>
            <translation>با دوربین «سفارشی» الزامی است؛ بر مقدار پیش‌فرض دوربین مقدم است.</translation>
        </message>
        <message>
            <source>Sensor width (mm) — required with Custom</source>
            <translation>عرض حسگر (mm) — با «سفارشی» الزامی است</translation>
        </message>
        <message>
            <source>Image width (px) — required with Custom</source>
            <translation>عرض تصویر (px) — با «سفارشی» الزامی است</translation>
        </message>
        <message>
            <source>Focal length, true (mm) — required with Custom</source>
            <translation>فاصلهٔ کانونی واقعی (mm) — با «سفارشی» الزامی است</translation>
        </message>
        <message>
            <source>GSD calculator report</source>
            <translation>گزارش محاسبه‌گر GSD</translation>
        </message>
    </context>
    <context>
        <name>IdwDtmAlgorithm</name>
        <message>
            <source>DTM by inverse distance weighting (IDW)</source>
            <translation>مدل رقومی زمین به روش وزن‌دهی معکوس فاصله (IDW)</translation>
        </message>
        <message>
            <source>dtm,dem,idw,inverse distance,interpolation,lidar,ground,gdal_grid,invdistnn,raster</source>
            <translation>dtm,dem,idw,معکوس فاصله,درون‌یابی,لایدار,زمین,gdal_grid,invdistnn,رستر</translation>
        </message>
        <message>
            <source>&lt;p&gt;Interpolates a terrain raster from the ground points of a LAS/LAZ file by inverse distance weighting (Shepard 1968): ẑ = Σ w&lt;sub&gt;i&lt;/sub&gt; z&lt;sub&gt;i&lt;/sub&gt; / Σ w&lt;sub&gt;i&lt;/sub&gt;, w&lt;sub&gt;i&lt;/sub&gt; = 1/d&lt;sub&gt;i&lt;/sub&gt;&lt;sup&gt;p&lt;/sup&gt;, over the nearest neighbours of each cell centre. Same semantics as &lt;code&gt;gdal_grid -a invdistnn&lt;/code&gt; (power, max_points, radius, min_points; a cell centre on a point takes its height exactly), but KD-tree based and processed in blocks: 1 M points onto 1 M cells take seconds.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=ground.laz CLASSES=2 CELL_SIZE=1 POWER=3 NEIGHBOURS=12 (the seed paper's best setting, RMSE 0.204 m at 62 GNSS points).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</source>
            <translation>&lt;p&gt;رستر ناهمواری زمین را از نقاط زمینی یک پروندهٔ LAS/LAZ به روش وزن‌دهی معکوس فاصله (Shepard 1968) درون‌یابی می‌کند: ẑ = Σ w&lt;sub&gt;i&lt;/sub&gt; z&lt;sub&gt;i&lt;/sub&gt; / Σ w&lt;sub&gt;i&lt;/sub&gt;، w&lt;sub&gt;i&lt;/sub&gt; = 1/d&lt;sub&gt;i&lt;/sub&gt;&lt;sup&gt;p&lt;/sup&gt;، روی نزدیک‌ترین همسایه‌های مرکز هر سلول. معنای پارامترها همانند &lt;code&gt;gdal_grid -a invdistnn&lt;/code&gt; است (power، max_points، radius، min_points؛ مرکز سلولی که روی یک نقطه بیفتد دقیقاً ارتفاع آن را می‌گیرد)، اما مبتنی بر درخت KD و با پردازش بلوکی: 1 میلیون نقطه روی 1 میلیون سلول چند ثانیه طول می‌کشد.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=ground.laz CLASSES=2 CELL_SIZE=1 POWER=3 NEIGHBOURS=12 (بهترین تنظیم مقالهٔ مبنا، RMSE = 0.204 متر روی 62 نقطهٔ GNSS).&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</translation>
        </message>
        <message>
            <source>Power p</source>
            <translation>توان p</translation>
        </message>
        <message>
            <source>Neighbours (0 = all within radius)</source>
            <translation>تعداد همسایه‌ها (0 = همهٔ نقاط درون شعاع)</translation>
        </message>
        <message>
            <source>Search radius (m, 0 = unlimited)</source>
            <translation>شعاع جست‌وجو (متر، 0 = نامحدود)</translation>
        </message>
        <message>
            <source>Minimum points</source>
            <translation>حداقل تعداد نقاط</translation>
        </message>
        <message>
            <source>IDW DTM</source>
            <translation>مدل رقومی زمین به روش IDW</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Power&lt;/b&gt; (POWER, default 2; the paper found 3 best).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Neighbours&lt;/b&gt; (NEIGHBOURS, default 12): nearest points used (gdal max_points); 0 = all points within the radius (needs RADIUS). More neighbours than points → error.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Search radius&lt;/b&gt; (RADIUS, m, default 0 = unlimited): only points within it are used (gdal radius).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum points&lt;/b&gt; (MIN_POINTS, default 0): cells with fewer neighbours within the radius are nodata (gdal min_points).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Outputs also the numbers N_POINTS, VALID_CELLS, NODATA_CELLS.&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;توان&lt;/b&gt; (POWER، پیش‌فرض 2؛ مقاله 3 را بهترین یافت).&lt;/li&gt;&lt;li&gt;&lt;b&gt;تعداد همسایه‌ها&lt;/b&gt; (NEIGHBOURS، پیش‌فرض 12): تعداد نزدیک‌ترین نقاطی که به کار می‌روند (max_points در gdal)؛ 0 = همهٔ نقاط درون شعاع (نیازمند RADIUS). همسایه‌های بیشتر از تعداد نقاط → خطا.&lt;/li&gt;&lt;li&gt;&lt;b&gt;شعاع جست‌وجو&lt;/b&gt; (RADIUS، متر، پیش‌فرض 0 = نامحدود): فقط نقاط درون آن به کار می‌روند (radius در gdal).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حداقل تعداد نقاط&lt;/b&gt; (MIN_POINTS، پیش‌فرض 0): سلول‌هایی که همسایه‌های کمتری درون شعاع دارند nodata می‌شوند (min_points در gdal).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;اعداد N_POINTS، VALID_CELLS و NODATA_CELLS نیز خروجی داده می‌شوند.&lt;/p&gt;</translation>
        </message>
    </context>
    <context>
        <name>KrigingDtmAlgorithm</name>
        <message>
            <source>DTM by kriging (ordinary / universal)</source>
            <translation>مدل رقومی زمین به روش کریجینگ (معمولی / عام)</translation>
        </message>
        <message>
            <source>dtm,dem,kriging,variogram,geostatistics,pykrige,interpolation,lidar,variance,cross-validation</source>
            <translation>dtm,dem,کریجینگ,واریوگرام,زمین‌آمار,pykrige,درون‌یابی,لایدار,واریانس,اعتبارسنجی متقابل</translation>
        </message>
        <message>
            <source>&lt;p&gt;Kriging (Matheron 1963; Cressie 1993) of the ground points of a LAS/LAZ file onto a raster, with a kriging variance (or standard deviation) raster. Ordinary kriging (unknown constant mean) or universal kriging with a linear drift. The variogram is fitted with PyKrige's estimator on a random subsample (or given by you); each cell is then kriged from its nearest points in batched local systems, so 1 M points onto a 1 km² grid at 1 m take about a minute instead of the n×n matrix that makes plain PyKrige run out of memory past ~100 k points.&lt;/p&gt;&lt;p&gt;&lt;b&gt;What is approximated&lt;/b&gt;: the variogram is fitted on a sample of point pairs (FIT_POINTS, reproducible with SEED), by default at the local scale. Local-neighbourhood kriging is not global kriging: only the NEIGHBOURS nearest points are weighted and the mean is re-estimated in every neighbourhood (quasi-stationarity). On terrain this follows the relief better than one global mean (it gave the lowest hold-out RMSE on all four ISPRS samples in the benchmark), but the two differ — typically by centimetres, by decimetres to metres at borders, gaps and steep slopes. With NEIGHBOURS equal to the number of points (≤ 6000) the result is global kriging, identical to PyKrige. With a linear drift the variogram is fitted on the residuals of a least-squares plane; points with identical x, y are merged (mean height). The kriging variance is model-based: check it with CV_POINTS (RMS standardised error near 1 means realistic variances).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=ground.laz CELL_SIZE=1 VARIOGRAM=spherical NEIGHBOURS=16 CV_POINTS=1000.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</source>
            <translation>&lt;p&gt;کریجینگ (Matheron 1963؛ Cressie 1993) نقاط زمینی یک پروندهٔ LAS/LAZ روی یک رستر، همراه با رستر واریانس کریجینگ (یا انحراف معیار). کریجینگ معمولی (میانگین ثابت نامعلوم) یا کریجینگ عام با روند خطی. واریوگرام با برآوردگر PyKrige روی یک زیرنمونهٔ تصادفی برازش داده می‌شود (یا شما آن را می‌دهید)؛ سپس هر سلول از نزدیک‌ترین نقاطش در دستگاه‌های محلیِ دسته‌ای کریجینگ می‌شود، بنابراین 1 میلیون نقطه روی شبکه‌ای به مساحت 1 کیلومتر مربع با سلول 1 متری حدود یک دقیقه طول می‌کشد، به‌جای ماتریس n×n که PyKrige معمولی را پس از حدود 100 هزار نقطه با کمبود حافظه روبه‌رو می‌کند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;چه چیزی تقریبی است&lt;/b&gt;: واریوگرام روی نمونه‌ای از زوج نقاط برازش داده می‌شود (FIT_POINTS، تکرارپذیر با SEED)، به‌طور پیش‌فرض در مقیاس محلی. کریجینگ در همسایگی محلی همان کریجینگ سراسری نیست: فقط NEIGHBOURS نقطهٔ نزدیک‌تر وزن می‌گیرند و میانگین در هر همسایگی دوباره برآورد می‌شود (شبه‌ایستایی). روی ناهمواری‌های زمین این روش پستی و بلندی را بهتر از یک میانگین سراسری دنبال می‌کند (در آزمون کارایی، کمترین RMSE روی نقاط کنارگذاشته را در هر چهار نمونهٔ ISPRS داد)، اما این دو با هم تفاوت دارند — معمولاً در حد سانتی‌متر، و در لبه‌ها، شکاف‌ها و شیب‌های تند در حد دسی‌متر تا متر. اگر NEIGHBOURS برابر تعداد نقاط باشد (≤ 6000)، نتیجه کریجینگ سراسری و یکسان با PyKrige است. با روند خطی، واریوگرام روی باقی‌مانده‌های یک صفحهٔ کمترین مربعات برازش داده می‌شود؛ نقاط با x و y یکسان ادغام می‌شوند (میانگین ارتفاع). واریانس کریجینگ مبتنی بر مدل است: آن را با CV_POINTS بسنجید (RMS خطای استانداردشدهٔ نزدیک به 1 یعنی واریانس‌ها واقع‌بینانه‌اند).&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=ground.laz CELL_SIZE=1 VARIOGRAM=spherical NEIGHBOURS=16 CV_POINTS=1000.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</translation>
        </message>
        <message>
            <source>Kriging type</source>
            <translation>نوع کریجینگ</translation>
        </message>
        <message>
            <source>Ordinary</source>
            <translation>معمولی</translation>
        </message>
        <message>
            <source>Universal (linear drift)</source>
            <translation>عام (روند خطی)</translation>
        </message>
        <message>
            <source>Variogram model</source>
            <translation>مدل واریوگرام</translation>
        </message>
        <message>
            <source>Neighbours per cell</source>
            <translation>تعداد همسایه‌ها برای هر سلول</translation>
        </message>
        <message>
            <source>Points for the variogram fit</source>
            <translation>تعداد نقاط برای برازش واریوگرام</translation>
        </message>
        <message>
            <source>Lag classes</source>
            <translation>تعداد کلاس‌های فاصلهٔ تأخیر (lag)</translation>
        </message>
        <message>
            <source>Maximum lag (m, 0 = auto: local scale)</source>
            <translation>بیشینهٔ فاصلهٔ تأخیر (متر، 0 = خودکار: مقیاس محلی)</translation>
        </message>
        <message>
            <source>Cross-validation points (0 = off)</source>
            <translation>نقاط اعتبارسنجی متقابل (0 = خاموش)</translation>
        </message>
        <message>
            <source>Random seed</source>
            <translation>بذر تصادفی</translation>
        </message>
        <message>
            <source>Kriging DTM</source>
            <translation>مدل رقومی زمین به روش کریجینگ</translation>
        </message>
        <message>
            <source>Write standard deviation instead of variance</source>
            <translation>نوشتن انحراف معیار به‌جای واریانس</translation>
        </message>
        <message>
            <source>Kriging variance</source>
            <translation>واریانس کریجینگ</translation>
        </message>
        <message>
            <source>Variogram: {}</source>
            <translation>واریوگرام: {}</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Kriging type&lt;/b&gt; (KRIGING_TYPE, 0 ordinary (default), 1 universal with linear drift).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Variogram model&lt;/b&gt; (VARIOGRAM, 0 linear, 1 power, 2 gaussian, 3 spherical (default), 4 exponential).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Variogram&lt;/b&gt; (VARIOGRAM_NUGGET m², VARIOGRAM_SILL m², VARIOGRAM_RANGE m; linear: VARIOGRAM_SLOPE; power: VARIOGRAM_SCALE, VARIOGRAM_EXPONENT; all optional numbers). Empty = fitted automatically. The sill includes the nugget; the range is the practical range.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Neighbours&lt;/b&gt; (NEIGHBOURS, default 16, ≥ 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Points for the variogram fit&lt;/b&gt; (FIT_POINTS, default 3000).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Lag classes&lt;/b&gt; (NLAGS, default 12) and &lt;b&gt;maximum lag&lt;/b&gt; (MAX_LAG, m, default 0 = automatic: three times the typical distance to the NEIGHBOURS-th neighbour, the scale local kriging uses, so the nugget and the short-range shape that set the weights and the variance are well sampled; the fitted sill and range then describe that local scale). For a classical field-scale fit give e.g. half the extent (Journel &amp;amp; Huijbregts 1978). A fitted nugget is raised to at least 1 % of the semivariance at the maximum lag, for numerical stability (Gaussian and power models).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cross-validation points&lt;/b&gt; (CV_POINTS, default 0 = off): leave-one-out on this many random points; reports ME, RMSE, mean standardised error (ideal 0) and RMS standardised error (ideal 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Seed&lt;/b&gt; (SEED, default 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Variance output&lt;/b&gt; (OUTPUT_VARIANCE, optional GeoTIFF): kriging variance (m²), or standard deviation (m) with VARIANCE_AS_STD.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: NUGGET, SILL, RANGE (NaN for linear/power), N_POINTS, VALID_CELLS, CV_ME, CV_RMSE, CV_MSE (NaN without cross-validation).&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;نوع کریجینگ&lt;/b&gt; (KRIGING_TYPE، 0 معمولی (پیش‌فرض)، 1 عام با روند خطی).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مدل واریوگرام&lt;/b&gt; (VARIOGRAM، 0 خطی، 1 توانی، 2 گوسی، 3 کروی (پیش‌فرض)، 4 نمایی).&lt;/li&gt;&lt;li&gt;&lt;b&gt;واریوگرام&lt;/b&gt; (VARIOGRAM_NUGGET متر²، VARIOGRAM_SILL متر²، VARIOGRAM_RANGE متر؛ خطی: VARIOGRAM_SLOPE؛ توانی: VARIOGRAM_SCALE و VARIOGRAM_EXPONENT؛ همه اعداد اختیاری). خالی = برازش خودکار. آستانه شامل اثر قطعه‌ای است؛ دامنه، دامنهٔ عملی است.&lt;/li&gt;&lt;li&gt;&lt;b&gt;تعداد همسایه‌ها&lt;/b&gt; (NEIGHBOURS، پیش‌فرض 16، ≥ 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;تعداد نقاط برای برازش واریوگرام&lt;/b&gt; (FIT_POINTS، پیش‌فرض 3000).&lt;/li&gt;&lt;li&gt;&lt;b&gt;تعداد کلاس‌های فاصلهٔ تأخیر&lt;/b&gt; (NLAGS، پیش‌فرض 12) و &lt;b&gt;بیشینهٔ فاصلهٔ تأخیر&lt;/b&gt; (MAX_LAG، متر، پیش‌فرض 0 = خودکار: سه برابر فاصلهٔ معمول تا همسایهٔ NEIGHBOURS-ام، یعنی مقیاسی که کریجینگ محلی به کار می‌برد، تا اثر قطعه‌ای و شکل واریوگرام در فواصل کوتاه، که وزن‌ها و واریانس را تعیین می‌کنند، به‌خوبی نمونه‌برداری شوند؛ در این حالت سقف و دامنهٔ برازش‌شده همان مقیاس محلی را توصیف می‌کنند). برای برازش کلاسیک در مقیاس کل منطقه، مثلاً نصف محدوده را بدهید (Journel &amp;amp; Huijbregts 1978). اثر قطعه‌ای برازش‌شده برای پایداری عددی دست‌کم تا 1 % نیم‌واریانس (semivariance) در بیشینهٔ فاصلهٔ تأخیر بالا برده می‌شود (مدل‌های گوسی و توانی).&lt;/li&gt;&lt;li&gt;&lt;b&gt;نقاط اعتبارسنجی متقابل&lt;/b&gt; (CV_POINTS، پیش‌فرض 0 = خاموش): حذف‌یکی روی این تعداد نقطهٔ تصادفی؛ ME، RMSE، میانگین خطای استانداردشده (ایده‌آل 0) و RMS خطای استانداردشده (ایده‌آل 1) را گزارش می‌کند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;بذر تصادفی&lt;/b&gt; (SEED، پیش‌فرض 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;خروجی واریانس&lt;/b&gt; (OUTPUT_VARIANCE، GeoTIFF اختیاری): واریانس کریجینگ (متر²)، یا انحراف معیار (متر) با VARIANCE_AS_STD.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;اعداد خروجی: NUGGET، SILL، RANGE (برای خطی/توانی NaN)، N_POINTS، VALID_CELLS، CV_ME، CV_RMSE، CV_MSE (بدون اعتبارسنجی متقابل NaN).&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Variogram nugget (m², empty = fit)</source>
            <translation>اثر قطعه‌ای واریوگرام (متر²، خالی = برازش)</translation>
        </message>
        <message>
            <source>Variogram sill, nugget included (m², empty = fit)</source>
            <translation>آستانهٔ واریوگرام با اثر قطعه‌ای (متر²، خالی = برازش)</translation>
        </message>
        <message>
            <source>Variogram practical range (m, empty = fit)</source>
            <translation>دامنهٔ عملی واریوگرام (متر، خالی = برازش)</translation>
        </message>
        <message>
            <source>Linear variogram slope (m²/m)</source>
            <translation>شیب واریوگرام خطی (متر²/متر)</translation>
        </message>
        <message>
            <source>Power variogram scale</source>
            <translation>مقیاس واریوگرام توانی</translation>
        </message>
        <message>
            <source>Power variogram exponent (0–2)</source>
            <translation>توان واریوگرام توانی (0–2)</translation>
        </message>
        <message>
            <source>Variogram parameters as text (old form)</source>
            <translation>پارامترهای واریوگرام به‌صورت متن (شکل قدیمی)</translation>
        </message>
    </context>
    <context>
        <name>LidarQaAlgorithm</name>
        <message>
            <source>Point density and quality (with parameter advice)</source>
            <translation>تراکم و کیفیت نقاط (با توصیهٔ پارامترها)</translation>
        </message>
        <message>
            <source>Density rasters, gaps, duplicates and noise of a cloud, and the filter window and DTM cell its density supports.</source>
            <translation>رسترهای تراکم، شکاف‌ها، نقاط تکراری و نویز یک ابر، و پنجرهٔ فیلتر و سلول مدل رقومی زمین که تراکم آن پشتیبانی می‌کند.</translation>
        </message>
        <message>
            <source>density,quality,qa,lasinfo,gaps,duplicates,noise,scan angle,returns,advice,lidar</source>
            <translation>تراکم,کیفیت,qa,lasinfo,شکاف‌ها,تکراری‌ها,نویز,زاویهٔ اسکن,بازتاب‌ها,توصیه,لیدار</translation>
        </message>
        <message>
            <source>&lt;p&gt;Checks a LAS/LAZ cloud before processing: density rasters of all returns, last returns and ground points, cells with returns but no ground (gaps), histograms of returns and classes, duplicate points, the share of noise (classes 7, 18) and the scan-angle range. It then states which settings the density supports: the ground filter window (1–2 pts/m² → 2 m), the DTM cell size, LOD1 only below 1 pt/m² (about 0.6 pts/m² in the ELiT study), and the radius and tile of our slope-based and LSQ filters.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=tile.laz CELL_SIZE=5 OUTPUT=density.tif OUTPUT_HTML=qa.html.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las/.laz in a projected CRS (metres); a cloud in degrees is refused.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell size&lt;/b&gt; (CELL_SIZE, m, default 5, &amp;gt; 0): cell of the density rasters.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground classes&lt;/b&gt; (GROUND_CLASSES, default &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Density rasters&lt;/b&gt; (OUTPUT): GeoTIFF with four bands: all returns, last returns, ground (pts/m²), gap (1/0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional): HTML report with maps and advice.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: DENSITY, GROUND_DENSITY (pts/m²), GAP_SHARE, DUPLICATES, NOISE_SHARE, GROUND_WINDOW (m), DTM_CELL (m).&lt;/p&gt;</source>
            <translation>&lt;p&gt;یک ابر LAS/LAZ را پیش از پردازش بررسی می‌کند: رسترهای تراکم همهٔ بازتاب‌ها، آخرین بازتاب‌ها و نقاط زمین، سلول‌های دارای بازتاب ولی بدون زمین (شکاف‌ها)، هیستوگرام بازتاب‌ها و کلاس‌ها، نقاط تکراری، سهم نویز (کلاس‌های ۷ و ۱۸) و بازهٔ زاویهٔ اسکن. سپس می‌گوید تراکم داده چه تنظیماتی را پشتیبانی می‌کند: پنجرهٔ فیلتر زمین (۱ تا ۲ نقطه بر مترمربع ← ۲ متر)، اندازهٔ سلول مدل رقومی زمین، فقط LOD1 زیر ۱ نقطه بر مترمربع (حدود ۰٫۶ در مطالعهٔ ELiT)، و شعاع و کاشی فیلترهای شیب‌مبنا و LSQ ما.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=tile.laz CELL_SIZE=5 OUTPUT=density.tif OUTPUT_HTML=qa.html.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;ابر نقاط&lt;/b&gt; (INPUT): فایل ‎.las/.laz در سیستم تصویر مسطح (متر)؛ ابر بر حسب درجه پذیرفته نمی‌شود.&lt;/li&gt;&lt;li&gt;&lt;b&gt;اندازهٔ سلول&lt;/b&gt; (CELL_SIZE، متر، پیش‌فرض ۵، &amp;gt; 0): سلول رسترهای تراکم.&lt;/li&gt;&lt;li&gt;&lt;b&gt;کلاس‌های زمین&lt;/b&gt; (GROUND_CLASSES، پیش‌فرض &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;رسترهای تراکم&lt;/b&gt; (OUTPUT): GeoTIFF با چهار باند: همهٔ بازتاب‌ها، آخرین بازتاب‌ها، زمین (نقطه بر مترمربع)، شکاف (1/0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML، اختیاری): گزارش HTML با نقشه‌ها و توصیه‌ها.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;اعداد خروجی: DENSITY، GROUND_DENSITY (نقطه بر مترمربع)، GAP_SHARE، DUPLICATES، NOISE_SHARE، GROUND_WINDOW (متر)، DTM_CELL (متر).&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Cell size (m)</source>
            <translation>اندازهٔ سلول (متر)</translation>
        </message>
        <message>
            <source>Ground classes</source>
            <translation>کلاس‌های زمین</translation>
        </message>
        <message>
            <source>Density rasters</source>
            <translation>رسترهای تراکم</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
    </context>
    <context>
        <name>LidarToDtmAlgorithm</name>
        <message>
            <source>LiDAR to DTM with accuracy</source>
            <translation>از LiDAR تا DTM همراه با دقت</translation>
        </message>
        <message>
            <source>lidar,ground,filter,dtm,dem,idw,accuracy,rmse,check points,chain,all-or-nothing</source>
            <translation>لیدار,زمین,فیلتر,مدل رقومی زمین,dem,idw,دقت,rmse,نقاط کنترل,زنجیره,همه یا هیچ</translation>
        </message>
        <message>
            <source>&lt;p&gt;Classifies the ground of a LiDAR point cloud, interpolates a DTM from the ground points and measures its accuracy against check points, in one step. It writes all its outputs or none: when any step fails or is cancelled, no classified cloud, DTM or report is left behind.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=tile.laz CHECKPOINTS_CSV=gnss.csv CELL_SIZE=1 OUTPUT=classified.laz OUTPUT_DTM=dtm.tif OUTPUT_HTML=accuracy.html → the classified cloud, the DTM and the RMSE.&lt;/p&gt;&lt;p&gt;The steps are the recommended ground filter (the improved least-squares filter where the recommended one is not installed), the IDW DTM (power 3, 12 neighbours by default: the seed paper's best setting) and the DTM accuracy; the results equal those of the three algorithms run one after another. Before anything is written the CRS, the check points (no duplicates, inside the cloud's extent) and every output path are checked. The graphical model of the same name is its editable counterpart, without this guarantee.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt;: .las or .laz in a projected CRS (metres).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Remove low outliers first&lt;/b&gt; (default yes), with its search cell (m, default 5) and depth (m, default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;DTM cell size&lt;/b&gt; (m, default 1), &lt;b&gt;IDW power&lt;/b&gt; (default 3), &lt;b&gt;neighbours&lt;/b&gt; (default 12), &lt;b&gt;fill data gaps&lt;/b&gt; (default no) and a &lt;b&gt;CRS&lt;/b&gt; for a cloud without a CRS record.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Check points&lt;/b&gt;: a point layer (heights from a field or the geometry Z) or a CSV/TXT file (id, x, y, z) with its CRS; reprojection of x, y on request; bilinear (default) or nearest-cell sampling.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Outputs&lt;/b&gt;: classified cloud, DTM (GeoTIFF), check-point residuals and the DTM accuracy report; optional ground filter report and DTM report.&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;p&gt;زمین یک ابر نقاط LiDAR را طبقه‌بندی می‌کند، از نقاط زمین یک مدل رقومی زمین (DTM) درون‌یابی می‌کند و دقت آن را با نقاط کنترل می‌سنجد، همه در یک گام. همهٔ خروجی‌هایش را می‌نویسد یا هیچ‌کدام را: اگر هر گامی شکست بخورد یا لغو شود، هیچ ابر طبقه‌بندی‌شده، DTM یا گزارشی باقی نمی‌ماند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: &lt;span dir="ltr"&gt;INPUT=tile.laz CHECKPOINTS_CSV=gnss.csv CELL_SIZE=1 OUTPUT=classified.laz OUTPUT_DTM=dtm.tif OUTPUT_HTML=accuracy.html&lt;/span&gt; ← ابر طبقه‌بندی‌شده، DTM و RMSE.&lt;/p&gt;&lt;p&gt;گام‌ها عبارت‌اند از فیلتر زمین پیشنهادی (یا فیلتر کمترین مربعات بهبودیافته در جایی که پیشنهادی نصب نیست)، DTM به روش IDW (توان 3 و 12 همسایه به‌طور پیش‌فرض: بهترین تنظیم مقالهٔ مرجع) و دقت DTM؛ نتایج با اجرای پشت‌سرهم سه الگوریتم برابرند. پیش از نوشتن هر چیز، سیستم مختصات، نقاط کنترل (بدون تکرار و درون گسترهٔ ابر) و همهٔ مسیرهای خروجی بررسی می‌شوند. مدل گرافیکی هم‌نام، همتای ویرایش‌پذیر آن است، اما بدون این تضمین.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;ابر نقاط&lt;/b&gt;: فایل ‎.las‏ یا ‎.laz‏ در سیستم مختصات تصویری (متر).&lt;/li&gt;&lt;li&gt;&lt;b&gt;ابتدا نقاط پرت پایین حذف شوند&lt;/b&gt; (پیش‌فرض بله)، با سلول جست‌وجو (متر، پیش‌فرض 5) و عمق (متر، پیش‌فرض 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;اندازهٔ سلول DTM&lt;/b&gt; (متر، پیش‌فرض 1)، &lt;b&gt;توان IDW&lt;/b&gt; (پیش‌فرض 3)، &lt;b&gt;تعداد همسایه‌ها&lt;/b&gt; (پیش‌فرض 12)، &lt;b&gt;پر کردن شکاف‌های داده&lt;/b&gt; (پیش‌فرض خیر) و یک &lt;b&gt;سیستم مختصات&lt;/b&gt; برای ابری بدون رکورد سیستم مختصات.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نقاط کنترل&lt;/b&gt;: یک لایهٔ نقطه‌ای (ارتفاع از یک فیلد یا Z هندسه) یا یک فایل CSV/TXT ‏(id, x, y, z) با سیستم مختصاتش؛ تبدیل x و y در صورت درخواست؛ نمونه‌برداری دوخطی (پیش‌فرض) یا نزدیک‌ترین سلول.&lt;/li&gt;&lt;li&gt;&lt;b&gt;خروجی‌ها&lt;/b&gt;: ابر طبقه‌بندی‌شده، DTM ‏(GeoTIFF)، باقیمانده‌های نقاط کنترل و گزارش دقت DTM؛ و به‌طور اختیاری گزارش فیلتر زمین و گزارش DTM.&lt;/li&gt;&lt;/ul&gt;</translation>
        </message>
        <message>
            <source>DTM cell size (m)</source>
            <translation>اندازهٔ سلول مدل زمین (متر)</translation>
        </message>
        <message>
            <source>IDW power</source>
            <translation>توان IDW</translation>
        </message>
        <message>
            <source>IDW neighbours</source>
            <translation>تعداد همسایه‌های IDW</translation>
        </message>
        <message>
            <source>Fill data gaps in the DTM (interpolate far from ground points)</source>
            <translation>پر کردن شکاف‌های داده در DTM (درون‌یابی دور از نقاط زمین)</translation>
        </message>
        <message>
            <source>CRS override for a cloud without a CRS record</source>
            <translation>سیستم مختصات جایگزین برای ابری بدون رکورد سیستم مختصات</translation>
        </message>
        <message>
            <source>Check points (point layer)</source>
            <translation>نقاط چک (لایهٔ نقطه‌ای)</translation>
        </message>
        <message>
            <source>Height field (empty = geometry Z)</source>
            <translation>فیلد ارتفاع (خالی = Z هندسه)</translation>
        </message>
        <message>
            <source>Id field</source>
            <translation>فیلد شناسه</translation>
        </message>
        <message>
            <source>Check points (CSV/TXT file: id,x,y,z)</source>
            <translation>نقاط کنترل (فایل CSV/TXT: ‏id,x,y,z)</translation>
        </message>
        <message>
            <source>CRS of the check point file (default: DTM CRS)</source>
            <translation>سیستم مختصات پروندهٔ نقاط چک (پیش‌فرض: سیستم مختصات DTM)</translation>
        </message>
        <message>
            <source>Reproject check points to the DTM CRS</source>
            <translation>بازتصویر نقاط چک به سیستم مختصات DTM</translation>
        </message>
        <message>
            <source>Sampling</source>
            <translation>روش نمونه‌برداری</translation>
        </message>
        <message>
            <source>Bilinear</source>
            <translation>دوخطی</translation>
        </message>
        <message>
            <source>Nearest cell</source>
            <translation>نزدیک‌ترین سلول</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>مدل رقومی زمین (DTM)</translation>
        </message>
        <message>
            <source>Check-point residuals</source>
            <translation>باقیمانده‌های نقاط کنترل</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>DTM accuracy report</source>
            <translation>گزارش دقت مدل رقومی زمین</translation>
        </message>
        <message>
            <source>Ground filter report</source>
            <translation>گزارش فیلتر زمین</translation>
        </message>
        <message>
            <source>DTM report</source>
            <translation>گزارش مدل رقومی زمین</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط زمینی</translation>
        </message>
        <message>
            <source>The point cloud has no CRS record and no CRS was given; set the CRS parameter (e.g. EPSG:32632). No output was written.</source>
            <translation>ابر نقاط رکورد سیستم مختصات ندارد و سیستم مختصاتی هم داده نشده است؛ پارامتر CRS را تنظیم کنید (مثلاً EPSG:32632). هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>None of the {n} check points lies within the point cloud's extent (x {x0:.1f}–{x1:.1f}, y {y0:.1f}–{y1:.1f}); are they in another CRS? No output was written.</source>
            <translation>هیچ‌یک از {n} نقطهٔ کنترل درون گسترهٔ ابر نقاط نیست (x ‏{x0:.1f}–{x1:.1f}، y ‏{y0:.1f}–{y1:.1f})؛ آیا در سیستم مختصات دیگری‌اند؟ هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Choose the point cloud (a .las or .laz file).</source>
            <translation>ابر نقاط را انتخاب کنید (فایل ‎.las‏ یا ‎.laz‏).</translation>
        </message>
        <message>
            <source>Choose an output file for {}.</source>
            <translation>یک فایل خروجی برای {} انتخاب کنید.</translation>
        </message>
        <message>
            <source>Cell size must be &gt; 0 (metres); give e.g. 1.0.</source>
            <translation>اندازهٔ سلول باید &gt; 0 (متر) باشد؛ مثلاً 1.0 بدهید.</translation>
        </message>
        <message>
            <source>The ground filter found no ground point; no DTM can be interpolated. No output was written.</source>
            <translation>فیلتر زمین هیچ نقطهٔ زمینی نیافت؛ DTM قابل درون‌یابی نیست. هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
    </context>
    <context>
        <name>LsqGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (least-squares polynomial)</source>
            <translation>فیلتر نقاط زمینی (چندجمله‌ای کمترین مربعات)</translation>
        </message>
        <message>
            <source>lidar,ground,filter,bare earth,dtm,classification,least squares,polynomial,tiles,las,laz,isprs</source>
            <translation>لایدار,زمین,فیلتر,زمین لخت,dtm,طبقه‌بندی,کمترین مربعات,چندجمله‌ای,کاشی‌ها,las,laz,isprs</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Polynomial order (1 or 2)</source>
            <translation>درجهٔ چندجمله‌ای (1 یا 2)</translation>
        </message>
        <message>
            <source>Tile size (m)</source>
            <translation>اندازهٔ کاشی (متر)</translation>
        </message>
        <message>
            <source>Threshold T (m)</source>
            <translation>آستانهٔ T (متر)</translation>
        </message>
        <message>
            <source>Mode</source>
            <translation>حالت</translation>
        </message>
        <message>
            <source>Faithful (the paper)</source>
            <translation>مطابق (روش مقاله)</translation>
        </message>
        <message>
            <source>Improved (ours, beyond the paper)</source>
            <translation>بهبودیافته (افزودهٔ ما، فراتر از مقاله)</translation>
        </message>
        <message>
            <source>Maximum iterations per tile</source>
            <translation>حداکثر تکرار در هر کاشی</translation>
        </message>
        <message>
            <source>Stop tolerance on min/max/mean/std (m)</source>
            <translation>تلورانس توقف برای کمینه/بیشینه/میانگین/انحراف معیار (متر)</translation>
        </message>
        <message>
            <source>Random fitting subset per tile (points, 0 = all)</source>
            <translation>زیرمجموعهٔ تصادفی برازش در هر کاشی (نقطه، 0 = همه)</translation>
        </message>
        <message>
            <source>Random seed of the subset</source>
            <translation>بذر تصادفی زیرمجموعه</translation>
        </message>
        <message>
            <source>Minimum points per tile (0 = 3 × coefficients)</source>
            <translation>حداقل نقاط هر کاشی (0 = 3 × تعداد ضرایب)</translation>
        </message>
        <message>
            <source>Under-populated tiles</source>
            <translation>کاشی‌های کم‌نقطه</translation>
        </message>
        <message>
            <source>Borrow the nearest fitted tile's surface</source>
            <translation>استفاده از سطح نزدیک‌ترین کاشی برازش‌شده</translation>
        </message>
        <message>
            <source>Leave their points unclassified (class 0)</source>
            <translation>طبقه‌بندی‌نشده ماندن نقاط آن‌ها (کلاس 0)</translation>
        </message>
        <message>
            <source>Rejection</source>
            <translation>شیوهٔ رد نقاط</translation>
        </message>
        <message>
            <source>Re-weighted each iteration (a point may return)</source>
            <translation>وزن‌دهی دوباره در هر تکرار (نقطه ممکن است بازگردد)</translation>
        </message>
        <message>
            <source>Cumulative (a rejected point stays out)</source>
            <translation>تجمعی (نقطهٔ ردشده بیرون می‌ماند)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>Ground points only</source>
            <translation>فقط نقاط زمینی</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط زمینی</translation>
        </message>
        <message>
            <source>Other (object) points</source>
            <translation>نقاط دیگر (عوارض)</translation>
        </message>
        <message>
            <source>Low-noise points</source>
            <translation>نقاط نویز پایین</translation>
        </message>
        <message>
            <source>Unclassified points</source>
            <translation>نقاط طبقه‌بندی‌نشده</translation>
        </message>
        <message>
            <source>Tiles</source>
            <translation>کاشی‌ها</translation>
        </message>
        <message>
            <source>Points per second</source>
            <translation>نقطه در ثانیه</translation>
        </message>
        <message>
            <source>Choose an output file for the classified cloud (OUTPUT, .laz or .las).</source>
            <translation>یک پروندهٔ خروجی برای ابر طبقه‌بندی‌شده انتخاب کنید (OUTPUT، با پسوند .laz یا .las).</translation>
        </message>
        <message>
            <source>Reading {p}</source>
            <translation>در حال خواندن {p}</translation>
        </message>
        <message>
            <source>{step}: {n} points kept, ZMin {a:.2f}, ZMax {b:.2f}, ZMean {m:.2f}, σ {s:.2f}; tiles iterating: {t}</source>
            <translation>{step}: {n} نقطه نگه داشته شد، ZMin {a:.2f}، ZMax {b:.2f}، ZMean {m:.2f}، σ {s:.2f}؛ کاشی‌های در حال تکرار: {t}</translation>
        </message>
        <message>
            <source>Ground {g}, other {o}, low noise {z}, unclassified {u}; {t} tiles; {s:.1f} s</source>
            <translation>زمینی {g}، سایر {o}، نویز پایین {z}، طبقه‌بندی‌نشده {u}؛ {t} کاشی؛ {s:.1f} ثانیه</translation>
        </message>
        <message>
            <source>&lt;p&gt;Separates bare-earth points from buildings and vegetation in an airborne LiDAR cloud by fitting least-squares polynomial surfaces per square tile (Damascus Univ. J. Eng. Sci. 29(2), 2013). In every tile the surface is fitted, points more than THRESHOLD above it are dropped, and the fit is repeated until the minimum, maximum, mean and standard deviation of the kept heights stop changing (TOLERANCE) or MAX_ITERATIONS; then every point with z ≤ ẑ + THRESHOLD is ground. Any classification already in the file is ignored and replaced.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Output classes&lt;/b&gt; (ASPRS): 2 ground, 1 other (buildings, vegetation), 7 low noise (pre-filter), 0 never classified (only with SPARSE_TILES = leave unclassified). Every other attribute of every point, the point format, scales, offsets, VLRs and CRS are copied unchanged.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=tile.laz TILE_SIZE=50 THRESHOLD=0.5 ORDER=2 OUTPUT=classified.laz GROUND_OUTPUT=ground.laz OUTPUT_HTML=report.html&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las or .laz file, projected CRS in metres.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Order&lt;/b&gt; (ORDER, default 2): 1 = plane z = b0 + b1·x + b2·y; 2 = quadratic z = b0 + b1·x² + b2·y² + b3·xy + b4·x + b5·y (better on every sample of the paper).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Tile size&lt;/b&gt; (TILE_SIZE, m, default 50): larger than the largest building, so that every tile holds ground (paper: 100 m for large buildings, 50 m for small ones). Tiles are square, anchored at the minimum x, y.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Threshold&lt;/b&gt; (THRESHOLD, m, default 0.5): 0.5–1.0 m, larger on steeper terrain.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Mode&lt;/b&gt; (MODE, default Faithful): Faithful = the paper. Improved = ours, beyond the paper: coarse-to-fine tiles (2, 1, ½, ¼ × TILE_SIZE) fitted on overlapping windows, each level started from the previous level's ground, and a threshold that grows with the surface slope (by 2.5 m per unit gradient, at most 1 m). On the ISPRS samples it lowers the mean total error from 8.9 % (paper) to about 4.9 % with one parameter set; it costs about 15 times the time and twice the memory of the faithful mode (about 2 M points/s and 100 bytes per point in faithful mode).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Remove low outliers first&lt;/b&gt; (NOISE, default yes): points far below their neighbours become class 7 and take no part in the fit (NOISE_RADIUS, m, default 5: neighbourhood cell; NOISE_THRESHOLD, m, default 1: depth below the neighbours).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Maximum iterations&lt;/b&gt; (MAX_ITERATIONS, default 5, the paper's tables) and &lt;b&gt;stop tolerance&lt;/b&gt; (TOLERANCE, m, default 0.01).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Random fitting subset per tile&lt;/b&gt; (SUBSET_SIZE, points, default 0 = all; the paper used 5000) and its &lt;b&gt;seed&lt;/b&gt; (SEED). All points are classified.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum points per tile&lt;/b&gt; (MIN_POINTS, default 0 = 3 × the number of coefficients) and &lt;b&gt;under-populated tiles&lt;/b&gt; (SPARSE_TILES): borrow the nearest fitted tile's surface (default) or leave their points unclassified (class 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Rejection&lt;/b&gt; (REJECTION): re-weighted (default; a point dropped earlier may return when the surface moves) or cumulative (dropped for good).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Outputs&lt;/b&gt;: classified cloud (OUTPUT, .laz or .las), optional ground-only cloud (GROUND_OUTPUT), optional HTML report (OUTPUT_HTML) with the parameters, class counts, the per-iteration statistics of the paper's Tables 1–2, per-tile statistics, time and points per second; optional CSV of every tile's iterations and coefficients (TILE_STATS); numbers N_GROUND, N_OTHER, N_NOISE, N_UNCLASSIFIED, N_TILES, POINTS_PER_SECOND.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Measure the result against reference labels with &lt;i&gt;Ground filter accuracy&lt;/i&gt;. Nothing is written when the run fails or is cancelled.&lt;/p&gt;</source>
            <translation>&lt;p&gt;نقاط زمین لخت را از ساختمان‌ها و پوشش گیاهی در ابر نقاط لایدار هوایی جدا می‌کند، با برازش سطوح چندجمله‌ای کمترین مربعات در هر کاشی مربعی (مجلهٔ علوم مهندسی دانشگاه دمشق 29(2)، 2013). در هر کاشی سطح برازش داده می‌شود، نقاطی که بیش از THRESHOLD بالاتر از آن‌اند کنار گذاشته می‌شوند، و برازش تکرار می‌شود تا کمینه، بیشینه، میانگین و انحراف معیار ارتفاع‌های نگه‌داشته‌شده دیگر تغییر نکنند (TOLERANCE) یا به MAX_ITERATIONS برسد؛ سپس هر نقطه با z ≤ ẑ + THRESHOLD زمینی است. هر طبقه‌بندی موجود در پرونده نادیده گرفته و جایگزین می‌شود.&lt;/p&gt;&lt;p&gt;&lt;b&gt;کلاس‌های خروجی&lt;/b&gt; (ASPRS): 2 زمینی، 1 سایر (ساختمان، پوشش گیاهی)، 7 نویز پایین (پیش‌فیلتر)، 0 هرگز طبقه‌بندی‌نشده (فقط با SPARSE_TILES = طبقه‌بندی‌نشده ماندن). همهٔ ویژگی‌های دیگر هر نقطه، قالب نقطه، ضرایب مقیاس، آفست‌ها، VLRها و سیستم مختصات بدون تغییر کپی می‌شوند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=tile.laz TILE_SIZE=50 THRESHOLD=0.5 ORDER=2 OUTPUT=classified.laz GROUND_OUTPUT=ground.laz OUTPUT_HTML=report.html&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;ابر نقاط&lt;/b&gt; (INPUT): پروندهٔ .las یا .laz، با سیستم مختصات تصویرشده به متر.&lt;/li&gt;&lt;li&gt;&lt;b&gt;درجه&lt;/b&gt; (ORDER، پیش‌فرض 2): 1 = صفحه z = b0 + b1·x + b2·y؛ 2 = درجه‌دوم z = b0 + b1·x² + b2·y² + b3·xy + b4·x + b5·y (در همهٔ نمونه‌های مقاله بهتر).&lt;/li&gt;&lt;li&gt;&lt;b&gt;اندازهٔ کاشی&lt;/b&gt; (TILE_SIZE، متر، پیش‌فرض 50): بزرگ‌تر از بزرگ‌ترین ساختمان، تا هر کاشی نقاط زمینی داشته باشد (مقاله: 100 متر برای ساختمان‌های بزرگ، 50 متر برای ساختمان‌های کوچک). کاشی‌ها مربعی‌اند و از کمینهٔ x و y آغاز می‌شوند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;آستانه&lt;/b&gt; (THRESHOLD، متر، پیش‌فرض 0.5): 0.5–1.0 متر، و در زمین‌های پرشیب‌تر بیشتر.&lt;/li&gt;&lt;li&gt;&lt;b&gt;حالت&lt;/b&gt; (MODE، پیش‌فرض: مطابق): مطابق = روش مقاله. بهبودیافته = افزودهٔ ما، فراتر از مقاله: کاشی‌های درشت به ریز (2، 1، ½، ¼ × TILE_SIZE) که روی پنجره‌های همپوشان برازش می‌شوند، هر سطح از نقاط زمینی سطح قبلی آغاز می‌شود، و آستانه‌ای که با شیب سطح افزایش می‌یابد (2.5 متر به ازای هر واحد گرادیان، حداکثر 1 متر). روی نمونه‌های ISPRS میانگین خطای کل را با یک مجموعه پارامتر از 8.9 % (مقاله) به حدود 4.9 % کاهش می‌دهد؛ حدود 15 برابر زمان و دو برابر حافظهٔ حالت مطابق را می‌گیرد (در حالت مطابق حدود 2 میلیون نقطه در ثانیه و 100 بایت برای هر نقطه).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حذف نقاط پرت پایین در آغاز&lt;/b&gt; (NOISE، پیش‌فرض: بله): نقاطی که بسیار پایین‌تر از همسایه‌های خود هستند کلاس 7 می‌گیرند و در برازش شرکت نمی‌کنند (NOISE_RADIUS، متر، پیش‌فرض 5: سلول همسایگی؛ NOISE_THRESHOLD، متر، پیش‌فرض 1: عمق زیر همسایه‌ها).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حداکثر تکرار&lt;/b&gt; (MAX_ITERATIONS، پیش‌فرض 5، مطابق جدول‌های مقاله) و &lt;b&gt;تلورانس توقف&lt;/b&gt; (TOLERANCE، متر، پیش‌فرض 0.01).&lt;/li&gt;&lt;li&gt;&lt;b&gt;زیرمجموعهٔ تصادفی برازش در هر کاشی&lt;/b&gt; (SUBSET_SIZE، نقطه، پیش‌فرض 0 = همه؛ مقاله 5000 به کار برده است) و &lt;b&gt;بذر تصادفی&lt;/b&gt; آن (SEED). همهٔ نقاط طبقه‌بندی می‌شوند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;حداقل نقاط هر کاشی&lt;/b&gt; (MIN_POINTS، پیش‌فرض 0 = 3 × تعداد ضرایب) و &lt;b&gt;کاشی‌های کم‌نقطه&lt;/b&gt; (SPARSE_TILES): استفاده از سطح نزدیک‌ترین کاشی برازش‌شده (پیش‌فرض) یا طبقه‌بندی‌نشده ماندن نقاط آن‌ها (کلاس 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;شیوهٔ رد نقاط&lt;/b&gt; (REJECTION): وزن‌دهی دوباره (پیش‌فرض؛ نقطه‌ای که پیش‌تر رد شده ممکن است با جابه‌جایی سطح بازگردد) یا تجمعی (برای همیشه رد می‌شود).&lt;/li&gt;&lt;li&gt;&lt;b&gt;خروجی‌ها&lt;/b&gt;: ابر طبقه‌بندی‌شده (OUTPUT، .laz یا .las)، ابر فقط نقاط زمینی به‌اختیار (GROUND_OUTPUT)، گزارش HTML اختیاری (OUTPUT_HTML) با پارامترها، تعداد نقاط هر کلاس، آماره‌های هر تکرار مطابق جدول‌های 1–2 مقاله، آماره‌های هر کاشی، زمان و تعداد نقطه در ثانیه؛ پروندهٔ CSV اختیاری از تکرارها و ضرایب هر کاشی (TILE_STATS)؛ اعداد N_GROUND، N_OTHER، N_NOISE، N_UNCLASSIFIED، N_TILES، POINTS_PER_SECOND.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;نتیجه را با &lt;i&gt;دقت فیلتر نقاط زمینی&lt;/i&gt; در برابر برچسب‌های مرجع بسنجید. اگر اجرا شکست بخورد یا لغو شود، چیزی نوشته نمی‌شود.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Per-tile iteration statistics (CSV)</source>
            <translation>آماره‌های تکرار هر کاشی (CSV)</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>پرونده‌های CSV (*.csv)</translation>
        </message>
    </context>
    <context>
        <name>PtdGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (progressive TIN densification)</source>
            <translation>فیلتر زمین (متراکم‌سازی تدریجی TIN)</translation>
        </message>
        <message>
            <source>Axelsson's progressive TIN densification ground filter.</source>
            <translation>فیلتر زمین با متراکم‌سازی تدریجی TIN (Axelsson).</translation>
        </message>
        <message>
            <source>&lt;p&gt;Classifies a LAS/LAZ point cloud into ground (class 2), other points (class 1) and low noise (class 7) by progressive TIN densification (Axelsson 2000): seeds are the lowest points of overlapping parcels larger than the largest building; the TIN is densified with every point close enough to its facet and seen under a small enough angle from its vertices, until no point is added. Pits and spikes are removed first by a step filter.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=tile.laz OUTPUT=classified.laz MAX_BUILDING=50 for a town with 50 m buildings. On the 8 ISPRS samples its mean total error is 8.05 % at the defaults; use &lt;i&gt;Ground filter (recommended)&lt;/i&gt; unless you need a TIN filter.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las or .laz in a projected CRS (metres).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell&lt;/b&gt; (CELL, m, default 2): lowest point per cell for the step filter and the seeds.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Parcel size&lt;/b&gt; (MAX_BUILDING, m, default 30): larger than the largest building (30–50 m).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Distance to facet&lt;/b&gt; (MAX_DISTANCE, m, default 1.5) and &lt;b&gt;angle to vertices&lt;/b&gt; (MAX_ANGLE, degrees, default 18): densification limits.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Shortest facet edge&lt;/b&gt; (MIN_EDGE, m, default 1, advanced), &lt;b&gt;iteration cap&lt;/b&gt; (MAX_ITERATIONS, default 150, advanced).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Final distance&lt;/b&gt; (FINAL_DISTANCE, m, default 0.5): points this close to the final TIN are ground; &lt;b&gt;low-noise depth&lt;/b&gt; (LOW_NOISE_DEPTH, m, default 1.5): points deeper below it get class 7.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Seed drop&lt;/b&gt; (SEED_DROP, %, default 0.3, advanced): lowest share of each parcel skipped before picking its seed.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Remove low outliers first&lt;/b&gt; (NOISE, default yes; NOISE_RADIUS m, 5; NOISE_THRESHOLD m, 1).&lt;/li&gt;</source>
            <translation>&lt;p&gt;ابر نقاط LAS/LAZ را با متراکم‌سازی تدریجی TIN ‏(Axelsson 2000) به زمین (کلاس 2)، نقاط دیگر (کلاس 1) و نویز پایین (کلاس 7) طبقه‌بندی می‌کند: بذرها پایین‌ترین نقاط قطعه‌های هم‌پوشان بزرگ‌تر از بزرگ‌ترین ساختمان‌اند؛ TIN با هر نقطه‌ای که به اندازهٔ کافی به وجه خود نزدیک است و با زاویهٔ به اندازهٔ کافی کوچک از رأس‌های آن دیده می‌شود متراکم می‌شود تا وقتی که نقطه‌ای افزوده نشود. گودال‌ها و برآمدگی‌ها ابتدا با فیلتر پله حذف می‌شوند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=tile.laz OUTPUT=classified.laz MAX_BUILDING=50 برای شهری با ساختمان‌های 50 متری. میانگین خطای کل آن روی 8 نمونهٔ ISPRS با پیش‌فرض‌ها 8.05 % است؛ مگر به فیلتر TIN نیاز دارید، از &lt;i&gt;فیلتر زمین (پیشنهادی)&lt;/i&gt; استفاده کنید.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;ابر نقاط&lt;/b&gt; (INPUT): ‎.las یا ‎.laz در سیستم مختصات تصویری (متر).&lt;/li&gt;&lt;li&gt;&lt;b&gt;سلول&lt;/b&gt; (CELL، متر، پیش‌فرض 2): پایین‌ترین نقطهٔ هر سلول برای فیلتر پله و بذرها.&lt;/li&gt;&lt;li&gt;&lt;b&gt;اندازهٔ قطعه&lt;/b&gt; (MAX_BUILDING، متر، پیش‌فرض 30): بزرگ‌تر از بزرگ‌ترین ساختمان (30 تا 50 متر).&lt;/li&gt;&lt;li&gt;&lt;b&gt;فاصله تا وجه&lt;/b&gt; (MAX_DISTANCE، متر، پیش‌فرض 1.5) و &lt;b&gt;زاویه تا رأس‌ها&lt;/b&gt; (MAX_ANGLE، درجه، پیش‌فرض 18): حدود متراکم‌سازی.&lt;/li&gt;&lt;li&gt;&lt;b&gt;کوتاه‌ترین ضلع وجه&lt;/b&gt; (MIN_EDGE، متر، پیش‌فرض 1، پیشرفته)، &lt;b&gt;سقف تکرار&lt;/b&gt; (MAX_ITERATIONS، پیش‌فرض 150، پیشرفته).&lt;/li&gt;&lt;li&gt;&lt;b&gt;فاصلهٔ نهایی&lt;/b&gt; (FINAL_DISTANCE، متر، پیش‌فرض 0.5): نقاطی که این اندازه به TIN نهایی نزدیک‌اند زمین‌اند؛ &lt;b&gt;عمق نویز پایین&lt;/b&gt; (LOW_NOISE_DEPTH، متر، پیش‌فرض 1.5): نقاط عمیق‌تر از آن زیر TIN کلاس 7 می‌گیرند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;کنارگذاری بذر&lt;/b&gt; (SEED_DROP، %، پیش‌فرض 0.3، پیشرفته): سهم پایین‌ترین نقاط هر قطعه که پیش از انتخاب بذر کنار گذاشته می‌شود.&lt;/li&gt;&lt;li&gt;&lt;b&gt;حذف نقاط پرت پایین در آغاز&lt;/b&gt; (NOISE، پیش‌فرض بله؛ NOISE_RADIUS متر، 5؛ NOISE_THRESHOLD متر، 1).&lt;/li&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;Reference: Axelsson, P. (2000). DEM generation from laser scanner data using adaptive TIN models. IAPRS XXXIII-B4, 110–117.&lt;/p&gt;</source>
            <translation>&lt;p&gt;مرجع: Axelsson, P. (2000). DEM generation from laser scanner data using adaptive TIN models. IAPRS XXXIII-B4, 110–117.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Cell (m)</source>
            <translation>سلول (متر)</translation>
        </message>
        <message>
            <source>Parcel size, &gt; largest building (m)</source>
            <translation>اندازهٔ قطعه، &gt; بزرگ‌ترین ساختمان (متر)</translation>
        </message>
        <message>
            <source>Distance to facet (m)</source>
            <translation>فاصله تا وجه (متر)</translation>
        </message>
        <message>
            <source>Angle to vertices (degrees)</source>
            <translation>زاویه تا رأس‌ها (درجه)</translation>
        </message>
        <message>
            <source>Final distance (m)</source>
            <translation>فاصلهٔ نهایی (متر)</translation>
        </message>
        <message>
            <source>Low-noise depth (m)</source>
            <translation>عمق نویز پایین (متر)</translation>
        </message>
        <message>
            <source>Shortest facet edge (m)</source>
            <translation>کوتاه‌ترین ضلع وجه (متر)</translation>
        </message>
        <message>
            <source>Iteration cap</source>
            <translation>سقف تکرار</translation>
        </message>
        <message>
            <source>Seed drop (%)</source>
            <translation>کنارگذاری بذر (%)</translation>
        </message>
        <message>
            <source>PTD: parcels {} m, distance {} m, angle {}°</source>
            <translation>PTD: قطعه‌ها {} متر، فاصله {} متر، زاویه {}°</translation>
        </message>
    </context>
    <context>
        <name>RectifyBatchAlgorithm</name>
        <message>
            <source>Rectify a folder of images with GCPs (batch)</source>
            <translation>تصحیح پوشه‌ای از تصاویر با نقاط کنترل (دسته‌ای)</translation>
        </message>
        <message>
            <source>Warps every image of a folder with its .points file and summarises the accuracy in one table.</source>
            <translation>هر تصویر پوشه را با فایل ‎.points‎ آن تصحیح و دقت را در یک جدول خلاصه می‌کند.</translation>
        </message>
        <message>
            <source>georeference,gcp,batch,folder,rectification,warp,rms</source>
            <translation>georeference,gcp,batch,folder,rectification,warp,rms,زمین‌مرجع,دسته‌ای,پوشه,تصحیح</translation>
        </message>
        <message>
            <source>&lt;p&gt;Rectifies every image of a folder that has its QGIS Georeferencer &lt;i&gt;.points&lt;/i&gt; file next to it (scan.tif + scan.tif.points), with a fixed transformation or the one recommended for each image, and writes one summary table: image, transformation, RMS_T, check-point / leave-one-out RMS_T, verdict.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT_FOLDER=scans TRANSFORMATION=8 OUTPUT_FOLDER=rectified OUTPUT_CSV=summary.csv&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Input folder&lt;/b&gt; (INPUT_FOLDER).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Transformation&lt;/b&gt; (TRANSFORMATION, default 8 = recommended per image; 0 polynomial of order ORDER, 1–3 polynomial 1–3, 4 linear, 5 Helmert, 6 projective, 7 thin-plate spline).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Polynomial order&lt;/b&gt; (ORDER, default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Refine GCPs&lt;/b&gt; (REFINE, default off): drop GCPs over the C5 limit 5·GR.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GCP CRS&lt;/b&gt; (GCP_CRS): for .points files without a '#CRS:' line.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resampling&lt;/b&gt; (RESAMPLING, default 0 = nearest).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Output folder&lt;/b&gt; (OUTPUT_FOLDER): image_rectified.tif per image, each written all-or-nothing.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Summary&lt;/b&gt; (OUTPUT_CSV, OUTPUT_HTML): one row per image; an image that cannot be rectified gets its error in the table and the others go on.&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;p&gt;هر تصویر پوشه را که فایل &lt;i&gt;.points&lt;/i&gt; مربوط به Georeferencer در QGIS کنارش است (scan.tif + scan.tif.points)، با یک تبدیل ثابت یا تبدیل پیشنهادی برای هر تصویر تصحیح می‌کند و یک جدول خلاصه می‌نویسد: تصویر، تبدیل، RMS_T، RMS_T نقاط چک / حذف‌یکی، رأی.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT_FOLDER=scans TRANSFORMATION=8 OUTPUT_FOLDER=rectified OUTPUT_CSV=summary.csv&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;پوشهٔ ورودی&lt;/b&gt; (INPUT_FOLDER).&lt;/li&gt;&lt;li&gt;&lt;b&gt;تبدیل&lt;/b&gt; (TRANSFORMATION، پیش‌فرض 8 = پیشنهادی برای هر تصویر؛ 0 چندجمله‌ای درجهٔ ORDER، 1–3 چندجمله‌ای 1–3، 4 خطی، 5 هلمرت، 6 تصویری، 7 اسپلاین صفحهٔ نازک).&lt;/li&gt;&lt;li&gt;&lt;b&gt;درجهٔ چندجمله‌ای&lt;/b&gt; (ORDER، پیش‌فرض 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;پالایش نقاط&lt;/b&gt; (REFINE، پیش‌فرض خاموش): حذف نقاط بالای حد C5 یعنی 5·GR.&lt;/li&gt;&lt;li&gt;&lt;b&gt;سیستم مختصات نقاط&lt;/b&gt; (GCP_CRS): برای فایل‌های .points بدون سطر '#CRS:'.&lt;/li&gt;&lt;li&gt;&lt;b&gt;بازنمونه‌گیری&lt;/b&gt; (RESAMPLING، پیش‌فرض 0 = نزدیک‌ترین).&lt;/li&gt;&lt;li&gt;&lt;b&gt;پوشهٔ خروجی&lt;/b&gt; (OUTPUT_FOLDER): ‏image_rectified.tif برای هر تصویر، هر کدام همه‌یا‌هیچ نوشته می‌شود.&lt;/li&gt;&lt;li&gt;&lt;b&gt;خلاصه&lt;/b&gt; (OUTPUT_CSV، OUTPUT_HTML): یک سطر برای هر تصویر؛ خطای تصویری که تصحیح نشود در جدول می‌آید و بقیه ادامه می‌یابند.&lt;/li&gt;&lt;/ul&gt;</translation>
        </message>
        <message>
            <source>Folder of images with .points files</source>
            <translation>پوشهٔ تصاویر با فایل‌های .points</translation>
        </message>
        <message>
            <source>Transformation</source>
            <translation>تبدیل</translation>
        </message>
        <message>
            <source>polynomial of order ORDER</source>
            <translation>چندجمله‌ای درجهٔ ORDER</translation>
        </message>
        <message>
            <source>polynomial order 1 (affine)</source>
            <translation>چندجمله‌ای درجهٔ 1 (آفین)</translation>
        </message>
        <message>
            <source>polynomial order 2</source>
            <translation>چندجمله‌ای درجهٔ 2</translation>
        </message>
        <message>
            <source>polynomial order 3</source>
            <translation>چندجمله‌ای درجهٔ 3</translation>
        </message>
        <message>
            <source>linear (shift and scale per axis)</source>
            <translation>خطی (انتقال و مقیاس برای هر محور)</translation>
        </message>
        <message>
            <source>Helmert (shift, scale, rotation)</source>
            <translation>هلمرت (انتقال، مقیاس، دوران)</translation>
        </message>
        <message>
            <source>projective (homography)</source>
            <translation>تصویری (هموگرافی)</translation>
        </message>
        <message>
            <source>thin-plate spline</source>
            <translation>اسپلاین صفحهٔ نازک</translation>
        </message>
        <message>
            <source>recommended (lowest check-point / leave-one-out error)</source>
            <translation>پیشنهادی (کمترین خطای نقاط چک / حذف‌یکی)</translation>
        </message>
        <message>
            <source>Polynomial order (1–3)</source>
            <translation>درجهٔ چندجمله‌ای (1–3)</translation>
        </message>
        <message>
            <source>Refine GCPs: drop the worst while over the tolerance</source>
            <translation>پالایش نقاط: حذف بدترین تا وقتی بالای تلورانس است</translation>
        </message>
        <message>
            <source>CRS of the GCP map coordinates (if the file does not say)</source>
            <translation>سیستم مختصاتِ مختصات نقشه‌ای نقاط کنترل (اگر پرونده آن را مشخص نکند)</translation>
        </message>
        <message>
            <source>Resampling</source>
            <translation>بازنمونه‌برداری</translation>
        </message>
        <message>
            <source>Folder of rectified images</source>
            <translation>پوشهٔ تصاویر تصحیح‌شده</translation>
        </message>
        <message>
            <source>Summary table</source>
            <translation>جدول خلاصه</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>پرونده‌های CSV (*.csv)</translation>
        </message>
        <message>
            <source>Summary report</source>
            <translation>گزارش خلاصه</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
    </context>
    <context>
        <name>RectifyGcpAlgorithm</name>
        <message>
            <source>georeference,georeferencer,gcp,ground control points,polynomial,rectification,warp,gdalwarp,rms,accuracy</source>
            <translation>زمین‌مرجع‌سازی,georeferencer,gcp,نقاط کنترل زمینی,چندجمله‌ای,تصحیح هندسی,warp,gdalwarp,rms,دقت</translation>
        </message>
        <message>
            <source>Target CRS [default: the GCP CRS]</source>
            <translation>سیستم مختصات مقصد [پیش‌فرض: سیستم مختصات نقاط کنترل]</translation>
        </message>
        <message>
            <source>Resampling</source>
            <translation>بازنمونه‌برداری</translation>
        </message>
        <message>
            <source>Output resolution (target CRS units) [default: GR]</source>
            <translation>قدرت تفکیک خروجی (به واحد سیستم مختصات مقصد) [پیش‌فرض: GR]</translation>
        </message>
        <message>
            <source>Output nodata value</source>
            <translation>مقدار nodata خروجی</translation>
        </message>
        <message>
            <source>Rectified image</source>
            <translation>تصویر تصحیح‌شده</translation>
        </message>
        <message>
            <source>Accuracy report</source>
            <translation>گزارش دقت</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>OUTPUT must be a GeoTIFF file (.tif); got {0}.</source>
            <translation>OUTPUT باید پروندهٔ GeoTIFF (.tif) باشد؛ مقدار داده‌شده: {0}.</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Target CRS&lt;/b&gt; (TARGET_CRS, default the GCP CRS): output CRS; GDAL reprojects after the polynomial.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resampling&lt;/b&gt; (RESAMPLING, default 0 = nearest neighbour as in the paper): 0 near, 1 bilinear, 2 cubic, 3 cubic spline, 4 Lanczos, 5 average, 6 mode.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Output resolution&lt;/b&gt; (RESOLUTION, target-CRS units, default GR).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Nodata&lt;/b&gt; (NODATA, optional): value outside the image footprint (default: the input's nodata, else 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Rectified image&lt;/b&gt; (OUTPUT): GeoTIFF (written under a temporary name, renamed on success; nothing is left behind on failure).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional): HTML accuracy report.&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;سیستم مختصات مقصد&lt;/b&gt; (TARGET_CRS، پیش‌فرض سیستم مختصات نقاط کنترل): سیستم مختصات خروجی؛ GDAL پس از اعمال چندجمله‌ای بازتصویر می‌کند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;بازنمونه‌برداری&lt;/b&gt; (RESAMPLING، پیش‌فرض 0 = نزدیک‌ترین همسایه مانند مقاله): 0 نزدیک‌ترین همسایه، 1 دوخطی، 2 مکعبی، 3 اسپلاین مکعبی، 4 Lanczos، 5 میانگین، 6 مُد.&lt;/li&gt;&lt;li&gt;&lt;b&gt;قدرت تفکیک خروجی&lt;/b&gt; (RESOLUTION، به واحد سیستم مختصات مقصد، پیش‌فرض GR).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مقدار nodata&lt;/b&gt; (NODATA، اختیاری): مقدار بیرون از محدودهٔ تصویر (پیش‌فرض: nodata ورودی، وگرنه 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;تصویر تصحیح‌شده&lt;/b&gt; (OUTPUT): GeoTIFF (با نامی موقت نوشته می‌شود و پس از موفقیت تغییر نام می‌یابد؛ در صورت شکست چیزی باقی نمی‌ماند).&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML، اختیاری): گزارش دقت HTML.&lt;/li&gt;&lt;/ul&gt;</translation>
        </message>
        <message>
            <source>Rectify image with GCPs</source>
            <translation>تصحیح تصویر با نقاط کنترل زمینی</translation>
        </message>
        <message>
            <source>&lt;p&gt;Rectifies (warps) an image with ground control points through GDAL: a polynomial of order 1–3, a linear, Helmert, projective or thin-plate-spline transformation, or the one with the lowest check-point / leave-one-out error (as &lt;i&gt;gdalwarp -order N&lt;/i&gt; / &lt;i&gt;-tps&lt;/i&gt;), and writes the accuracy report. The input image is never modified.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=scan.tif GCP_FILE=scan.tif.points TRANSFORMATION=8 REFINE=true OUTPUT=scan_rect.tif OUTPUT_HTML=scan_rect.html&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Image&lt;/b&gt; (INPUT): the raster to rectify.&lt;/li&gt;</source>
            <translation>&lt;p&gt;تصویری را با نقاط کنترل زمینی از طریق GDAL تصحیح (بازنمونه) می‌کند: چندجمله‌ای درجهٔ 1–3، تبدیل خطی، هلمرت، تصویری یا اسپلاین صفحهٔ نازک، یا تبدیلی با کمترین خطای نقاط چک / حذف‌یکی (مانند &lt;i&gt;gdalwarp -order N&lt;/i&gt; / &lt;i&gt;-tps&lt;/i&gt;)، و گزارش دقت را می‌نویسد. تصویر ورودی هرگز تغییر نمی‌کند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=scan.tif GCP_FILE=scan.tif.points TRANSFORMATION=8 REFINE=true OUTPUT=scan_rect.tif OUTPUT_HTML=scan_rect.html&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;تصویر&lt;/b&gt; (INPUT): رستری که باید تصحیح شود.&lt;/li&gt;</translation>
        </message>
    </context>
    <context>
        <name>SlopeGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (slope-based)</source>
            <translation>فیلتر نقاط زمینی (مبتنی بر شیب)</translation>
        </message>
        <message>
            <source>lidar,las,laz,ground,filter,classification,dtm,bare earth,vosselman,slope,point cloud</source>
            <translation>لایدار,las,laz,زمین,فیلتر,طبقه‌بندی,dtm,زمین لخت,vosselman,شیب,ابر نقاط</translation>
        </message>
        <message>
            <source>&lt;p&gt;Classifies a LAS/LAZ point cloud into ground (class 2) and non-ground (class 1) with Vosselman's (2000) slope-based filter: a point is non-ground when some neighbour at horizontal distance 0 &amp;lt; d ≤ r lies more than d·tan θ + h below it. Single pass, neighbours from the whole cloud, exact (labels identical to a brute-force check of every pair) and fast (about a million points per second on one core at r = 3 m). Low outliers get class 7; every other attribute is copied unchanged. The input classification is ignored.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: the forest study's setting RADIUS=3 SLOPE=44 HEIGHT_TOLERANCE=0 allows a rise of 2.90 m at 3 m. Tune r and θ to your data with &lt;i&gt;Slope filter threshold sweep&lt;/i&gt;.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las or .laz file in a projected CRS (metres).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Radius r&lt;/b&gt; (RADIUS, m, default 10, &amp;gt; 0): neighbourhood radius. An object is removed only within r of its edge, so r must exceed half the width of the largest building to remove; larger r costs more time.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Slope threshold θ&lt;/b&gt; (SLOPE, degrees, default 40, strictly between 0 and 90): the steepest terrain kept. Allowed rise at 3 m: 2.52 m (40°), 2.90 m (44°), 3.33 m (48°), 3.84 m (52°), 4.45 m (56°), 5.20 m (60°).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Height tolerance h&lt;/b&gt; (HEIGHT_TOLERANCE, m, default 0.2, ≥ 0): extra rise allowed for every pair, absorbs ranging noise between close points; 0 is the rule as published.&lt;/li&gt;</source>
            <translation>&lt;p&gt;یک ابر نقاط LAS/LAZ را با فیلتر مبتنی بر شیب Vosselman (2000) به زمینی (کلاس 2) و غیرزمینی (کلاس 1) طبقه‌بندی می‌کند: نقطه‌ای غیرزمینی است که همسایه‌ای در فاصلهٔ افقی 0 &lt; d ≤ r بیش از d·tan θ + h پایین‌تر از آن باشد. یک‌گذره، با همسایه‌ها از کل ابر، دقیق (برچسب‌ها با بررسی کامل همهٔ زوج‌ها یکسان‌اند) و سریع (حدود یک میلیون نقطه در ثانیه روی یک هستهٔ پردازنده با r = 3 متر). نقاط پرت پایین کلاس 7 می‌گیرند؛ همهٔ ویژگی‌های دیگر بدون تغییر کپی می‌شوند. طبقه‌بندی ورودی نادیده گرفته می‌شود.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: تنظیم مطالعهٔ جنگل RADIUS=3 SLOPE=44 HEIGHT_TOLERANCE=0 در فاصلهٔ 3 متر اختلاف ارتفاع 2.90 متر را مجاز می‌داند. r و θ را با &lt;i&gt;پیمایش آستانه‌های فیلتر شیب&lt;/i&gt; برای داده‌های خود تنظیم کنید.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;ابر نقاط&lt;/b&gt; (INPUT): پروندهٔ .las یا .laz در سیستم مختصات تصویرشده (متر).&lt;/li&gt;&lt;li&gt;&lt;b&gt;شعاع r&lt;/b&gt; (RADIUS، متر، پیش‌فرض 10، &gt; 0): شعاع همسایگی. یک عارضه فقط تا فاصلهٔ r از لبه‌اش حذف می‌شود، پس r باید از نصف عرض بزرگ‌ترین ساختمانی که باید حذف شود بیشتر باشد؛ r بزرگ‌تر زمان بیشتری می‌برد.&lt;/li&gt;&lt;li&gt;&lt;b&gt;آستانهٔ شیب θ&lt;/b&gt; (SLOPE، درجه، پیش‌فرض 40، اکیداً بین 0 و 90): تندترین شیب زمینی که نگه داشته می‌شود. اختلاف ارتفاع مجاز در 3 متر: 2.52 متر (40°)، 2.90 متر (44°)، 3.33 متر (48°)، 3.84 متر (52°)، 4.45 متر (56°)، 5.20 متر (60°).&lt;/li&gt;&lt;li&gt;&lt;b&gt;تلورانس ارتفاعی h&lt;/b&gt; (HEIGHT_TOLERANCE، متر، پیش‌فرض 0.2، ≥ 0): اختلاف ارتفاع اضافی مجاز برای هر زوج، که نویز فاصله‌یابی میان نقاط نزدیک را جذب می‌کند؛ 0 همان قاعدهٔ منتشرشده است.&lt;/li&gt;</translation>
        </message>
        <message>
            <source>Radius r (m)</source>
            <translation>شعاع r (متر)</translation>
        </message>
        <message>
            <source>Slope threshold θ (degrees)</source>
            <translation>آستانهٔ شیب θ (درجه)</translation>
        </message>
        <message>
            <source>Height tolerance h (m)</source>
            <translation>تلورانس ارتفاعی h (متر)</translation>
        </message>
        <message>
            <source>Keep existing noise classes (7, 18)</source>
            <translation>حفظ کلاس‌های نویز موجود (7, 18)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط زمینی</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>Points read</source>
            <translation>نقاط خوانده‌شده</translation>
        </message>
        <message>
            <source>Ground points (class 2)</source>
            <translation>نقاط زمینی (کلاس 2)</translation>
        </message>
        <message>
            <source>Non-ground points (class 1)</source>
            <translation>نقاط غیرزمینی (کلاس 1)</translation>
        </message>
        <message>
            <source>Low outliers (class 7)</source>
            <translation>نقاط پرت پایین (کلاس 7)</translation>
        </message>
        <message>
            <source>Filter speed (points/s)</source>
            <translation>سرعت فیلتر (نقطه/ثانیه)</translation>
        </message>
        <message>
            <source>Slope filter: r = {} m, θ = {}°, h = {} m, {} returns, mode {}</source>
            <translation>فیلتر شیب: r = {} متر، θ = {}°، h = {} متر، بازگشت‌ها: {}، حالت: {}</translation>
        </message>
        <message>
            <source>{} points: {} ground, {} non-ground, {} low outliers; filter {:.1f} s</source>
            <translation>{} نقطه: {} زمینی، {} غیرزمینی، {} پرت پایین؛ فیلتر {:.1f} ثانیه</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Keep existing noise classes&lt;/b&gt; (KEEP_NOISE, default yes, advanced): points already classified 7 or 18 keep their class and take no part.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classified point cloud&lt;/b&gt; (OUTPUT, .laz/.las): every point, classes 2/1/7.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground points&lt;/b&gt; (GROUND_OUTPUT, optional): only the ground points.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional): counts, settings, allowed-rise table, speed.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: N_POINTS, N_GROUND, N_NONGROUND, N_NOISE, POINTS_PER_SECOND (filter step only).&lt;/p&gt;&lt;p&gt;Reference: Vosselman, G. (2000). Slope based filtering of laser altimetry data. IAPRS XXXIII-B3, 935–942.&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;حفظ کلاس‌های نویز موجود&lt;/b&gt; (KEEP_NOISE، پیش‌فرض: بله، پیشرفته): نقاطی که از پیش کلاس 7 یا 18 دارند کلاس خود را نگه می‌دارند و در فیلتر شرکت نمی‌کنند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ابر نقاط طبقه‌بندی‌شده&lt;/b&gt; (OUTPUT، .laz/.las): همهٔ نقاط، با کلاس‌های 2/1/7.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نقاط زمینی&lt;/b&gt; (GROUND_OUTPUT، اختیاری): فقط نقاط زمینی.&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML، اختیاری): تعدادها، تنظیمات، جدول اختلاف ارتفاع مجاز، سرعت.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;اعداد خروجی: N_POINTS، N_GROUND، N_NONGROUND، N_NOISE، POINTS_PER_SECOND (فقط مرحلهٔ فیلتر).&lt;/p&gt;&lt;p&gt;مرجع: Vosselman, G. (2000). Slope based filtering of laser altimetry data. IAPRS XXXIII-B3, 935–942.&lt;/p&gt;</translation>
        </message>
    </context>
    <context>
        <name>SlopeThresholdSweepAlgorithm</name>
        <message>
            <source>Slope filter threshold sweep</source>
            <translation>پیمایش آستانه‌های فیلتر شیب</translation>
        </message>
        <message>
            <source>lidar,ground,filter,vosselman,slope,threshold,tuning,accuracy,type I,type II,kappa,isprs</source>
            <translation>لایدار,زمین,فیلتر,vosselman,شیب,آستانه,تنظیم,دقت,نوع اول,نوع دوم,کاپا,isprs</translation>
        </message>
        <message>
            <source>&lt;p&gt;Runs the slope-based ground filter for every combination of slope thresholds θ, radii r and height tolerances h and reports, against reference labels, Type I error (ground rejected), Type II error (objects accepted as ground — the forest study's "error" column, which alone always favours low θ), total error and Cohen's kappa (Sithole &amp;amp; Vosselman 2004), then picks the best setting. One exact neighbourhood pass per radius and tolerance: every threshold then costs a single comparison per point.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: the forest study: SLOPES=40:60:4 RADII=3 HEIGHT_TOLERANCES=0. ISPRS reference samples: INPUT=samp31.laz (its own classification is the reference).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): LAS/LAZ. Its classification is never used to filter.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Reference cloud&lt;/b&gt; (REFERENCE, optional): a labelled copy of the same points in the same order; empty = the input's own classification (e.g. the ISPRS samples).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground classes&lt;/b&gt; (GROUND_CLASSES, default "2"): reference classes counted as ground; all others are objects.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Slope thresholds&lt;/b&gt; (SLOPES, degrees, default "30,35,40,44,48,52,56,60"): a list or start:stop:step.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Radii&lt;/b&gt; (RADII, m, default "10") and &lt;b&gt;height tolerances&lt;/b&gt; (HEIGHT_TOLERANCES, m, default "0.2"): lists; each value is one pass.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Best by&lt;/b&gt; (METRIC, default 0): 0 lowest total error, 1 highest kappa, 2 lowest Type I, 3 lowest Type II.&lt;/li&gt;</source>
            <translation>&lt;p&gt;فیلتر زمینی مبتنی بر شیب را برای هر ترکیب از آستانه‌های شیب θ، شعاع‌های r و تلورانس‌های ارتفاعی h اجرا می‌کند و در برابر برچسب‌های مرجع، خطای نوع اول (رد نقاط زمینی)، خطای نوع دوم (پذیرش عوارض به‌عنوان زمین — ستون «خطا» در مطالعهٔ جنگل، که به‌تنهایی همیشه θ پایین را ترجیح می‌دهد)، خطای کل و ضریب کاپای کوهن (Sithole &amp; Vosselman 2004) را گزارش می‌کند و سپس بهترین تنظیم را برمی‌گزیند. برای هر شعاع و تلورانس یک گذر دقیق همسایگی انجام می‌شود: پس از آن هر آستانه فقط یک مقایسه به ازای هر نقطه هزینه دارد.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: مطالعهٔ جنگل: SLOPES=40:60:4 RADII=3 HEIGHT_TOLERANCES=0. نمونه‌های مرجع ISPRS: INPUT=samp31.laz (طبقه‌بندی خودش مرجع است).&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;ابر نقاط&lt;/b&gt; (INPUT): LAS/LAZ. طبقه‌بندی آن هرگز برای فیلتر کردن به کار نمی‌رود.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ابر مرجع&lt;/b&gt; (REFERENCE، اختیاری): رونوشتی برچسب‌دار از همان نقاط با همان ترتیب؛ خالی = طبقه‌بندی خود ورودی (مثلاً نمونه‌های ISPRS).&lt;/li&gt;&lt;li&gt;&lt;b&gt;کلاس‌های زمینی&lt;/b&gt; (GROUND_CLASSES، پیش‌فرض "2"): کلاس‌های مرجعی که زمینی به شمار می‌آیند؛ بقیه عارضه‌اند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;آستانه‌های شیب&lt;/b&gt; (SLOPES، درجه، پیش‌فرض "30,35,40,44,48,52,56,60"): فهرست یا start:stop:step (شروع:پایان:گام).&lt;/li&gt;&lt;li&gt;&lt;b&gt;شعاع‌ها&lt;/b&gt; (RADII، متر، پیش‌فرض "10") و &lt;b&gt;تلورانس‌های ارتفاعی&lt;/b&gt; (HEIGHT_TOLERANCES، متر، پیش‌فرض "0.2"): فهرست؛ هر مقدار یک گذر است.&lt;/li&gt;&lt;li&gt;&lt;b&gt;معیار انتخاب بهترین&lt;/b&gt; (METRIC، پیش‌فرض 0): 0 کمترین خطای کل، 1 بیشترین کاپا، 2 کمترین نوع اول، 3 کمترین نوع دوم.&lt;/li&gt;</translation>
        </message>
        <message>
            <source>Reference cloud (empty = the input's classification)</source>
            <translation>ابر مرجع (خالی = طبقه‌بندی خود ورودی)</translation>
        </message>
        <message>
            <source>Reference ground classes</source>
            <translation>کلاس‌های زمینی مرجع</translation>
        </message>
        <message>
            <source>Slope thresholds θ (degrees; list or start:stop:step)</source>
            <translation>آستانه‌های شیب θ (درجه؛ فهرست یا شروع:پایان:گام)</translation>
        </message>
        <message>
            <source>Radii r (m; list)</source>
            <translation>شعاع‌های r (متر؛ فهرست)</translation>
        </message>
        <message>
            <source>Height tolerances h (m; list)</source>
            <translation>تلورانس‌های ارتفاعی h (متر؛ فهرست)</translation>
        </message>
        <message>
            <source>Best by</source>
            <translation>معیار انتخاب بهترین</translation>
        </message>
        <message>
            <source>Lowest total error</source>
            <translation>کمترین خطای کل</translation>
        </message>
        <message>
            <source>Highest kappa</source>
            <translation>بیشترین کاپا</translation>
        </message>
        <message>
            <source>Lowest Type I error</source>
            <translation>کمترین خطای نوع اول</translation>
        </message>
        <message>
            <source>Lowest Type II error</source>
            <translation>کمترین خطای نوع دوم</translation>
        </message>
        <message>
            <source>Sweep table</source>
            <translation>جدول پیمایش</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>پرونده‌های CSV (*.csv)</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>Classified with the best setting</source>
            <translation>طبقه‌بندی‌شده با بهترین تنظیم</translation>
        </message>
        <message>
            <source>Best radius (m)</source>
            <translation>بهترین شعاع (متر)</translation>
        </message>
        <message>
            <source>Best slope threshold (degrees)</source>
            <translation>بهترین آستانهٔ شیب (درجه)</translation>
        </message>
        <message>
            <source>Best height tolerance (m)</source>
            <translation>بهترین تلورانس ارتفاعی (متر)</translation>
        </message>
        <message>
            <source>Type I error at the best setting (%)</source>
            <translation>خطای نوع اول در بهترین تنظیم (%)</translation>
        </message>
        <message>
            <source>Type II error at the best setting (%)</source>
            <translation>خطای نوع دوم در بهترین تنظیم (%)</translation>
        </message>
        <message>
            <source>Total error at the best setting (%)</source>
            <translation>خطای کل در بهترین تنظیم (%)</translation>
        </message>
        <message>
            <source>Kappa at the best setting (%)</source>
            <translation>کاپا در بهترین تنظیم (%)</translation>
        </message>
        <message>
            <source>Settings evaluated</source>
            <translation>تعداد تنظیمات ارزیابی‌شده</translation>
        </message>
        <message>
            <source>Best setting</source>
            <translation>بهترین تنظیم</translation>
        </message>
        <message>
            <source>Sweeping {} thresholds × {} radii × {} tolerances</source>
            <translation>پیمایش {} آستانه × {} شعاع × {} تلورانس</translation>
        </message>
        <message>
            <source>Best ({}): {} — total {:.2f} %</source>
            <translation>بهترین ({}): {} — خطای کل {:.2f} %</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Sweep table&lt;/b&gt; (OUTPUT_CSV): one row per setting: radius_m, slope_deg, height_tolerance_m, allowed_rise_at_r_m, n_ground, a, b, c, d, type1_pct, type2_pct, total_pct, kappa_pct.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML): the table, the best setting and a chart of the errors against θ.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classified with the best setting&lt;/b&gt; (OUTPUT, optional LAS/LAZ).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: BEST_RADIUS, BEST_SLOPE, BEST_HEIGHT_TOLERANCE, BEST_TYPE1, BEST_TYPE2, BEST_TOTAL, BEST_KAPPA (percent), N_SETTINGS.&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;جدول پیمایش&lt;/b&gt; (OUTPUT_CSV): یک سطر برای هر تنظیم: radius_m, slope_deg, height_tolerance_m, allowed_rise_at_r_m, n_ground, a, b, c, d, type1_pct, type2_pct, total_pct, kappa_pct.&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML): جدول، بهترین تنظیم و نمودار خطاها بر حسب θ.&lt;/li&gt;&lt;li&gt;&lt;b&gt;طبقه‌بندی‌شده با بهترین تنظیم&lt;/b&gt; (OUTPUT، LAS/LAZ اختیاری).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;اعداد خروجی: BEST_RADIUS، BEST_SLOPE، BEST_HEIGHT_TOLERANCE، BEST_TYPE1، BEST_TYPE2، BEST_TOTAL، BEST_KAPPA (درصد)، N_SETTINGS.&lt;/p&gt;</translation>
        </message>
    </context>
    <context>
        <name>TinDtmAlgorithm</name>
        <message>
            <source>DTM by TIN (Delaunay linear interpolation)</source>
            <translation>مدل رقومی زمین با TIN (درون‌یابی خطی دلونی)</translation>
        </message>
        <message>
            <source>Terrain raster from the planes of the ground points' Delaunay triangles, gaps left empty.</source>
            <translation>رستر زمین از صفحه‌های مثلث‌های دلونی نقاط زمین، با شکاف‌های خالی.</translation>
        </message>
        <message>
            <source>dtm,dem,tin,delaunay,triangulation,linear,gdal_grid,blast2dem,lidar,ground,raster</source>
            <translation>مدل رقومی زمین,dem,tin,دلونی,مثلث‌بندی,خطی,gdal_grid,blast2dem,لیدار,زمین,رستر</translation>
        </message>
        <message>
            <source>&lt;p&gt;Triangulates the ground points of a LAS/LAZ file (Delaunay, Qhull) and gives every cell centre the height of the plane of its triangle — the TIN DTM most practitioners default to, the method of &lt;code&gt;gdal_grid -a linear&lt;/code&gt;. Triangles with an edge longer than the maximum edge are dropped, so gaps under buildings or water stay nodata unless you fill them; cells outside the points' convex hull are always nodata.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=ground.laz CLASSES=2 CELL_SIZE=0.5 MAX_EDGE=0.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</source>
            <translation>&lt;p&gt;نقاط زمین یک فایل LAS/LAZ را مثلث‌بندی می‌کند (دلونی، Qhull) و به مرکز هر سلول ارتفاع صفحهٔ مثلث آن را می‌دهد — مدل رقومی زمین TIN که بیشتر کاربران به‌طور پیش‌فرض به کار می‌برند، همان روش &lt;code&gt;gdal_grid -a linear&lt;/code&gt;. مثلث‌هایی که ضلعی بلندتر از بیشینهٔ طول دارند حذف می‌شوند، بنابراین شکاف‌های زیر ساختمان‌ها یا روی آب بدون داده می‌مانند مگر آنکه پر کردن آن‌ها را بخواهید؛ سلول‌های بیرون از پوستهٔ محدب نقاط همیشه بدون داده‌اند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=ground.laz CLASSES=2 CELL_SIZE=0.5 MAX_EDGE=0.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Maximum triangle edge&lt;/b&gt; (MAX_EDGE, m, default 0 = automatic: ten mean point spacings, at least four cells): longer triangles are nodata.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Fill gaps&lt;/b&gt; (FILL_GAPS, default no): keep every triangle, bridging gaps inside the hull with flat facets.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Outputs also the numbers N_POINTS, N_TRIANGLES, VALID_CELLS, NODATA_CELLS.&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;بیشینهٔ طول ضلع مثلث&lt;/b&gt; (MAX_EDGE، متر، پیش‌فرض 0 = خودکار: ده برابر فاصلهٔ میانگین نقاط، دست‌کم چهار سلول): مثلث‌های بلندتر بدون داده می‌مانند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;پر کردن شکاف‌ها&lt;/b&gt; (FILL_GAPS، پیش‌فرض خیر): همهٔ مثلث‌ها نگه داشته می‌شوند و شکاف‌های درون پوسته با وجوه تخت پر می‌شوند.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;اعداد N_POINTS، N_TRIANGLES، VALID_CELLS و NODATA_CELLS نیز خروجی داده می‌شوند.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Maximum triangle edge (m, 0 = auto)</source>
            <translation>بیشینهٔ طول ضلع مثلث (متر، 0 = خودکار)</translation>
        </message>
        <message>
            <source>Fill gaps (keep long triangles)</source>
            <translation>پر کردن شکاف‌ها (نگه داشتن مثلث‌های بلند)</translation>
        </message>
        <message>
            <source>TIN DTM</source>
            <translation>مدل رقومی زمین TIN</translation>
        </message>
    </context>
    <context>
        <name>_GcpBase</name>
        <message>
            <source>Image (raster) to rectify</source>
            <translation>تصویر (رستر) برای تصحیح</translation>
        </message>
        <message>
            <source>Image (raster) the GCPs were measured on</source>
            <translation>تصویر (رستر) که نقاط کنترل روی آن اندازه‌گیری شده‌اند</translation>
        </message>
        <message>
            <source>GCP file (.points or CSV)</source>
            <translation>پروندهٔ نقاط کنترل زمینی (.points یا CSV)</translation>
        </message>
        <message>
            <source>GCP files (*.points *.csv *.txt);;All files (*.*)</source>
            <translation>پرونده‌های نقاط کنترل (*.points *.csv *.txt);;همهٔ پرونده‌ها (*.*)</translation>
        </message>
        <message>
            <source>…or GCP point layer</source>
            <translation>…یا لایهٔ نقطه‌ای نقاط کنترل</translation>
        </message>
        <message>
            <source>Layer field: image column</source>
            <translation>فیلد لایه: ستون تصویر</translation>
        </message>
        <message>
            <source>Layer field: image row</source>
            <translation>فیلد لایه: سطر تصویر</translation>
        </message>
        <message>
            <source>Layer field: point id</source>
            <translation>فیلد لایه: شناسهٔ نقطه</translation>
        </message>
        <message>
            <source>Layer field: enabled (1/0)</source>
            <translation>فیلد لایه: فعال (1/0)</translation>
        </message>
        <message>
            <source>Layer field: role (gcp/check)</source>
            <translation>فیلد لایه: نقش (gcp/check)</translation>
        </message>
        <message>
            <source>Layer field: weight (&gt; 0)</source>
            <translation>فیلد لایه: وزن (&gt; 0)</translation>
        </message>
        <message>
            <source>Image coordinates refer to</source>
            <translation>مختصات تصویر مربوط است به</translation>
        </message>
        <message>
            <source>pixel corners: (0,0) = top-left corner of the image (GDAL/QGIS)</source>
            <translation>گوشه‌های پیکسل: (0,0) = گوشهٔ بالا-چپ تصویر (GDAL/QGIS)</translation>
        </message>
        <message>
            <source>pixel centres: integer = centre of a pixel (0-based indices)</source>
            <translation>مراکز پیکسل: عدد صحیح = مرکز یک پیکسل (اندیس‌ها از 0)</translation>
        </message>
        <message>
            <source>CRS of the GCP map coordinates (if the file does not say)</source>
            <translation>سیستم مختصاتِ مختصات نقشه‌ای نقاط کنترل (اگر پرونده آن را مشخص نکند)</translation>
        </message>
        <message>
            <source>Polynomial order (1–3)</source>
            <translation>درجهٔ چندجمله‌ای (1–3)</translation>
        </message>
        <message>
            <source>Ground resolution GR (map units/pixel) [default: from the GCPs]</source>
            <translation>قدرت تفکیک زمینی GR (واحد نقشه/پیکسل) [پیش‌فرض: از نقاط کنترل]</translation>
        </message>
        <message>
            <source>INPUT: no image given or it cannot be opened; give a raster file.</source>
            <translation>INPUT: تصویری داده نشده یا باز نمی‌شود؛ یک پروندهٔ رستری بدهید.</translation>
        </message>
        <message>
            <source>INPUT: {0} is not a local raster file; save the image to a file first.</source>
            <translation>INPUT: {0} پروندهٔ رستری محلی نیست؛ ابتدا تصویر را در یک پرونده ذخیره کنید.</translation>
        </message>
        <message>
            <source>Give either GCP_FILE or GCP_LAYER, not both.</source>
            <translation>یا GCP_FILE یا GCP_LAYER را بدهید، نه هر دو.</translation>
        </message>
        <message>
            <source>No GCPs: give a GCP file (GCP_FILE, .points or CSV) or a point layer (GCP_LAYER with COL_FIELD and ROW_FIELD); no &lt;image&gt;.points file was found next to the image either.</source>
            <translation>نقطهٔ کنترلی وجود ندارد: یک پروندهٔ نقاط کنترل (GCP_FILE، .points یا CSV) یا یک لایهٔ نقطه‌ای (GCP_LAYER با COL_FIELD و ROW_FIELD) بدهید؛ پروندهٔ &lt;image&gt;.points هم کنار تصویر یافت نشد.</translation>
        </message>
        <message>
            <source>GCP_LAYER needs COL_FIELD and ROW_FIELD: the fields holding the image column and row of each point.</source>
            <translation>GCP_LAYER به COL_FIELD و ROW_FIELD نیاز دارد: فیلدهایی که ستون و سطر تصویر هر نقطه را در خود دارند.</translation>
        </message>
        <message>
            <source>GCP layer feature {0} has no geometry.</source>
            <translation>عارضهٔ {0} در لایهٔ نقاط کنترل هندسه ندارد.</translation>
        </message>
        <message>
            <source>The GCP map coordinates have no CRS: the file has no '#CRS:' line and GCP_CRS is not set. Set GCP_CRS (e.g. EPSG:22780) and run again.</source>
            <translation>مختصات نقشه‌ای نقاط کنترل سیستم مختصات ندارند: پرونده خط '#CRS:' ندارد و GCP_CRS تنظیم نشده است. GCP_CRS را تنظیم کنید (مثلاً EPSG:22780) و دوباره اجرا کنید.</translation>
        </message>
        <message>
            <source>The GCP CRS is geographic (degrees): the accuracy criteria need map units of length. Set TARGET_CRS (or GCP_CRS) to a projected CRS, e.g. the UTM zone of the image.</source>
            <translation>سیستم مختصات نقاط کنترل جغرافیایی (درجه) است: معیارهای دقت به واحدهای طولی نقشه نیاز دارند. TARGET_CRS (یا GCP_CRS) را روی یک سیستم مختصات تصویرشده تنظیم کنید، مثلاً زون UTM تصویر.</translation>
        </message>
        <message>
            <source>Transformation</source>
            <translation>تبدیل</translation>
        </message>
        <message>
            <source>polynomial of order ORDER</source>
            <translation>چندجمله‌ای درجهٔ ORDER</translation>
        </message>
        <message>
            <source>polynomial order 1 (affine)</source>
            <translation>چندجمله‌ای درجهٔ 1 (آفین)</translation>
        </message>
        <message>
            <source>polynomial order 2</source>
            <translation>چندجمله‌ای درجهٔ 2</translation>
        </message>
        <message>
            <source>polynomial order 3</source>
            <translation>چندجمله‌ای درجهٔ 3</translation>
        </message>
        <message>
            <source>linear (shift and scale per axis)</source>
            <translation>خطی (انتقال و مقیاس برای هر محور)</translation>
        </message>
        <message>
            <source>Helmert (shift, scale, rotation)</source>
            <translation>هلمرت (انتقال، مقیاس، دوران)</translation>
        </message>
        <message>
            <source>projective (homography)</source>
            <translation>تصویری (هموگرافی)</translation>
        </message>
        <message>
            <source>thin-plate spline</source>
            <translation>اسپلاین صفحهٔ نازک</translation>
        </message>
        <message>
            <source>recommended (lowest check-point / leave-one-out error)</source>
            <translation>پیشنهادی (کمترین خطای نقاط چک / حذف‌یکی)</translation>
        </message>
        <message>
            <source>Refine GCPs: drop the worst while over the tolerance</source>
            <translation>پالایش نقاط: حذف بدترین تا وقتی بالای تلورانس است</translation>
        </message>
        <message>
            <source>Refinement tolerance (map units) [default: C5 limit 5·GR]</source>
            <translation>تلورانس پالایش (واحد نقشه) [پیش‌فرض: حد C5 یعنی 5·GR]</translation>
        </message>
        <message>
            <source>Minimum GCPs kept by the refinement [default: minimum + 2]</source>
            <translation>حداقل نقاط باقی‌مانده پس از پالایش [پیش‌فرض: حداقل + 2]</translation>
        </message>
    </context>
    <context>
        <name>_GridAlgorithm</name>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Cell size (m)</source>
            <translation>اندازهٔ سلول (متر)</translation>
        </message>
        <message>
            <source>Extent</source>
            <translation>محدوده</translation>
        </message>
        <message>
            <source>CRS (overrides the LAS file's CRS)</source>
            <translation>سیستم مختصات (بر سیستم مختصات پروندهٔ LAS مقدم است)</translation>
        </message>
        <message>
            <source>Maximum distance to data (m, 0 = auto)</source>
            <translation>بیشینهٔ فاصله تا داده (متر، 0 = خودکار)</translation>
        </message>
        <message>
            <source>Fill data gaps (interpolate far from data)</source>
            <translation>پر کردن شکاف‌های داده (درون‌یابی دور از داده)</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>The point cloud has no CRS record and no CRS was given; set the CRS parameter (e.g. EPSG:32632). No output was written.</source>
            <translation>ابر نقاط رکورد سیستم مختصات ندارد و سیستم مختصاتی هم داده نشده است؛ پارامتر CRS را تنظیم کنید (مثلاً EPSG:32632). هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Cell size must be &gt; 0 (metres); give e.g. 1.0. No output was written.</source>
            <translation>اندازهٔ سلول باید &gt; 0 (متر) باشد؛ مثلاً 1.0 بدهید. هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Reading points of class(es) {} from {}</source>
            <translation>در حال خواندن نقاط کلاس(های) {} از {}</translation>
        </message>
        <message>
            <source>{} of {} points selected</source>
            <translation>{} نقطه از {} نقطه انتخاب شد</translation>
        </message>
        <message>
            <source>Classes used (none = all)</source>
            <translation>کلاس‌های به‌کاررفته (بدون انتخاب = همه)</translation>
        </message>
    </context>
    <context>
        <name>_GroundCommon</name>
        <message>
            <source>lidar,las,laz,ground,filter,classification,dtm,bare earth,point cloud</source>
            <translation>لیدار,las,laz,زمین,فیلتر,طبقه‌بندی,مدل رقومی زمین,زمین برهنه,ابر نقاط</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Keep existing noise classes (7, 18)</source>
            <translation>حفظ کلاس‌های نویز موجود (7, 18)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط زمینی</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
        <message>
            <source>Points read</source>
            <translation>نقاط خوانده‌شده</translation>
        </message>
        <message>
            <source>Ground points (class 2)</source>
            <translation>نقاط زمینی (کلاس 2)</translation>
        </message>
        <message>
            <source>Non-ground points (class 1)</source>
            <translation>نقاط غیرزمینی (کلاس 1)</translation>
        </message>
        <message>
            <source>Low outliers (class 7)</source>
            <translation>نقاط پرت پایین (کلاس 7)</translation>
        </message>
        <message>
            <source>Filter speed (points/s)</source>
            <translation>سرعت فیلتر (نقطه/ثانیه)</translation>
        </message>
        <message>
            <source>{} points: {} ground, {} non-ground, {} low outliers; filter {:.1f} s</source>
            <translation>{} نقطه: {} زمینی، {} غیرزمینی، {} پرت پایین؛ فیلتر {:.1f} ثانیه</translation>
        </message>
    </context>
    <context>
        <name>_SlopeCommon</name>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Returns filtered</source>
            <translation>بازگشت‌های فیلترشونده</translation>
        </message>
        <message>
            <source>All returns</source>
            <translation>همهٔ بازگشت‌ها</translation>
        </message>
        <message>
            <source>Last returns only</source>
            <translation>فقط بازگشت‌های آخر</translation>
        </message>
        <message>
            <source>Mode</source>
            <translation>حالت</translation>
        </message>
        <message>
            <source>Exact (Vosselman 2000)</source>
            <translation>دقیق (Vosselman 2000)</translation>
        </message>
        <message>
            <source>Terrain-adaptive (toolbox extension)</source>
            <translation>سازگار با ناهمواری زمین (افزودهٔ جعبه‌ابزار)</translation>
        </message>
        <message>
            <source>Adaptive mode: trend cell (m)</source>
            <translation>حالت سازگار: سلول روند (متر)</translation>
        </message>
        <message>
            <source>Adaptive mode: trend window, &gt; largest building (m)</source>
            <translation>حالت سازگار: پنجرهٔ روند، &gt; بزرگ‌ترین ساختمان (متر)</translation>
        </message>
        <message>
            <source>TREND_CELL and TREND_WINDOW must be &gt; 0 metres in adaptive mode (e.g. 10 and 60).</source>
            <translation>در حالت سازگار، TREND_CELL و TREND_WINDOW باید &gt; 0 متر باشند (مثلاً 10 و 60).</translation>
        </message>
        <message>
            <source>NOISE_RADIUS and NOISE_THRESHOLD must be &gt; 0 metres (e.g. 5 and 1), or switch the NOISE pre-filter off.</source>
            <translation>NOISE_RADIUS و NOISE_THRESHOLD باید &gt; 0 متر باشند (مثلاً 5 و 1)، یا پیش‌فیلتر NOISE را خاموش کنید.</translation>
        </message>
    </context>
</TS>
